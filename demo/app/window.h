/* SPDX-License-Identifier: MIT */
// window.h - the window, and the frame drawn in it: what the pictures
// (render.cpp) and the game in the window (controller.cpp) share.
#ifndef C2D_DEMO_WINDOW_H
#define C2D_DEMO_WINDOW_H

#include <SDL.h>

#include <string>
#include <vector>

#include "app/aim.h"
#include "app/canvas.h"
#include "app/draw_balls.h"
#include "app/draw_table.h"
#include "app/engine_view.h"
#include "app/hud.h"
#include "app/render.h"
#include "app/view.h"
#include "pool/sim.h"

namespace demo {

constexpr double kMaxPlaySpeed = 12.0;  // m/s at full power, a hard break
constexpr int kDefaultWidth = 1200;     // offscreen pictures, and windows when the display is unknown

// The scene is played on the pool table (not in the gas's box).
bool pool(const Simulation &sim);

// Where the table, the panel and the text go on a width x height canvas.
Screen layout_for(const Simulation &sim, int width, int height);

// The table and the panel's fixed parts, drawn once per canvas size.
class Backdrop {
public:
    const Canvas &get(const Simulation &sim, const TableShape &shape, const Screen &layout) {
        if (canvas_.width() != layout.width || canvas_.height() != layout.height) {
            canvas_ = Canvas(layout.width, layout.height);
            draw_table(canvas_, shape, layout, pool(sim) ? TableStyle::Pool : TableStyle::Box);
            draw_panel_base(canvas_, layout);
        }
        return canvas_;
    }

private:
    Canvas canvas_;
};

// A ball that has just fallen, shown sinking into its hole for a moment.
struct Drop {
    int number;
    double x, y, hole_x, hole_y;
    Mat3 pose;
    double age;  // s
};
constexpr double kDropSeconds = 0.2;

// What a frame shows over the table besides the balls.
struct Overlay {
    std::vector<Drop> drops;
    bool aiming = false;
    AimState aim;
    PanelState panel;
    bool help = false;
    std::string banner;
};

// A frame: the backdrop, the falling and the standing balls, the aim, the
// panel, then the help box or the banner (the gas: its disks and a line).
void draw_frame(Canvas &frame, const Canvas &backdrop, const Screen &layout, const Simulation &sim, const TableShape &shape,
                const BallPoses &poses, const Overlay &overlay);

// The object balls off the table.
std::vector<int> pocketed_numbers(const Simulation &sim);

struct Window {
    SDL_Window *window = nullptr;
    SDL_Renderer *renderer = nullptr;
    SDL_Texture *texture = nullptr;
    int texture_w = 0, texture_h = 0;
    Window() = default;
    Window(const Window &) = delete;
    Window &operator=(const Window &) = delete;
    ~Window() {
        if (texture) SDL_DestroyTexture(texture);
        if (renderer) SDL_DestroyRenderer(renderer);
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();  // also closes SDL's D-Bus connection
    }
    void output_size(int &w, int &h) const {
        if (SDL_GetRendererOutputSize(renderer, &w, &h) != 0 || w <= 0 || h <= 0) w = texture_w, h = texture_h;
    }
    // Shows a frame the size of the renderer's output.
    bool show(const Canvas &frame) {
        if (!texture || texture_w != frame.width() || texture_h != frame.height()) {
            if (texture) SDL_DestroyTexture(texture);
            texture = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_STREAMING, frame.width(), frame.height());
            texture_w = frame.width();
            texture_h = frame.height();
        }
        if (!texture || SDL_UpdateTexture(texture, nullptr, frame.pixels().data(), frame.width() * 4) != 0) return false;
        SDL_RenderClear(renderer);
        return SDL_RenderCopy(renderer, texture, nullptr, nullptr) == 0;
    }
};

// A window that fits the display's usable area (less room for its frame),
// resizable; the frame keeps the table's aspect with black bars.
WindowResult open_window(const Simulation &sim, Window &w, std::string &error);

}  // namespace demo

#endif
