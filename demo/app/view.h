/* SPDX-License-Identifier: MIT */
// view.h - where things go in the window: the table (rails included) and,
// for the pool scenes, the panel under it (status, power meter, spin
// selector), fitted to the canvas with the table's aspect kept and the rest
// left black (letterbox); and the map from the world (metres, y up) to the
// canvas (pixels, y down).
#ifndef C2D_DEMO_VIEW_H
#define C2D_DEMO_VIEW_H

#include <algorithm>
#include <cmath>

#include "app/canvas.h"

namespace demo {

struct RectF {
    float x, y, w, h;
    bool contains(float px, float py) const { return px >= x && py >= y && px < x + w && py < y + h; }
};

struct View {
    double scale = 1;           // pixels per metre
    double origin_x = 0, origin_y = 0;  // canvas position of the world's (0, 0)
    float px(double x) const { return static_cast<float>(origin_x + x * scale); }
    float py(double y) const { return static_cast<float>(origin_y - y * scale); }
    PointF at(double x, double y) const { return {px(x), py(y)}; }
    float length(double metres) const { return static_cast<float>(metres * scale); }
    double wx(double sx) const { return (sx - origin_x) / scale; }
    double wy(double sy) const { return (origin_y - sy) / scale; }
};

// The panel's height as a fraction of the table's drawn height.
constexpr double kPanelFraction = 0.2;

struct Screen {
    int width = 0, height = 0;  // the canvas
    RectF table{}, panel{};     // panel.h == 0 without a panel
    View view;

    // A table of length x width metres with rails of `rail`, in a canvas.
    Screen(int canvas_width, int canvas_height, double length, double width_m, double rail, bool with_panel)
        : width(canvas_width), height(canvas_height) {
        const double table_w = length + 2 * rail, table_h = width_m + 2 * rail;
        const double total_h = table_h * (with_panel ? 1 + kPanelFraction : 1.0);
        const double scale = std::min(canvas_width / table_w, canvas_height / total_h);
        const double left = std::floor((canvas_width - table_w * scale) / 2);
        const double top = std::floor((canvas_height - total_h * scale) / 2);
        table = {static_cast<float>(left), static_cast<float>(top), static_cast<float>(table_w * scale),
                 static_cast<float>(table_h * scale)};
        panel = {table.x, table.y + table.h, table.w, static_cast<float>((total_h - table_h) * scale)};
        view.scale = scale;
        view.origin_x = left + rail * scale;
        view.origin_y = top + (rail + width_m) * scale;
    }
    // The canvas size that fits a table (and panel) into max_w x max_h.
    static void fit(double length, double width_m, double rail, bool with_panel, int max_w, int max_h, int &w, int &h) {
        const double table_w = length + 2 * rail, table_h = (width_m + 2 * rail) * (with_panel ? 1 + kPanelFraction : 1.0);
        const double scale = std::min(max_w / table_w, max_h / table_h);
        w = static_cast<int>(std::lround(table_w * scale));
        h = static_cast<int>(std::lround(table_h * scale));
    }
};

}  // namespace demo

#endif
