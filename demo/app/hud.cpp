/* SPDX-License-Identifier: MIT */
// hud.cpp - see hud.h.  Sizes follow the panel's height, so the panel reads
// the same at any window size.
#include "app/hud.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/draw_balls.h"
#include "app/font.h"

namespace demo {

namespace {

constexpr Colour kPanel = rgb8(22, 24, 28);
constexpr Colour kText = rgb8(235, 235, 225);
constexpr Colour kDim = rgb8(150, 150, 150);

int text_scale(const Screen &layout) {
    const float unit = layout.panel.h > 0 ? layout.panel.h : layout.table.h * 0.2f;
    return std::max(1, static_cast<int>(std::lround(unit / 60.0f)));
}

float pad(const Screen &layout) { return std::max(4.0f, layout.panel.h * 0.08f); }

// The power meter's rectangle, left of the dial.
RectF meter_rect(const Screen &layout) {
    const Dial dial = spin_dial(layout);
    const float w = layout.panel.w * 0.2f, h = std::max(6.0f, layout.panel.h * 0.2f);
    return {dial.cx - dial.radius * 1.9f - w, layout.panel.y + layout.panel.h * 0.5f - h * 0.1f, w, h};
}

void draw_meter(Canvas &canvas, const Screen &layout, const PanelState &state) {
    const RectF r = meter_rect(layout);
    const int scale = text_scale(layout);
    char label[64];
    std::snprintf(label, sizeof label, "Power %4.1f m/s", state.power * state.max_speed);
    draw_text(canvas, label, static_cast<int>(r.x), static_cast<int>(r.y) - text_height(scale) - scale * 4,
              TextStyle{scale, kText, false});
    const int steps = static_cast<int>(r.w * std::clamp(state.power, 0.0, 1.0));
    for (int i = 0; i < steps; ++i) {
        const float f = static_cast<float>(i) / r.w;
        const Colour c = f < 0.5f ? mix(rgb8(40, 200, 80), rgb8(250, 220, 40), f * 2) : mix(rgb8(250, 220, 40), rgb8(235, 50, 40), f * 2 - 1);
        canvas.fill_rect(r.x + static_cast<float>(i), r.y, r.x + static_cast<float>(i) + 1, r.y + r.h, c);
    }
    for (int tick = 1; tick < 4; ++tick) {
        const float x = r.x + r.w * static_cast<float>(tick) / 4;
        canvas.fill_rect(x - 0.5f, r.y, x + 0.5f, r.y + r.h, {0, 0, 0}, 0.5f);
    }
}

void draw_dial(Canvas &canvas, const Screen &layout, const PanelState &state) {
    const Dial d = spin_dial(layout);
    const float tx = d.cx + static_cast<float>(state.side) * d.radius;
    const float ty = d.cy - static_cast<float>(state.topback) * d.radius;
    canvas.fill_disk(tx, ty, std::max(3.0f, d.radius * 0.13f), rgb8(40, 90, 200));
    canvas.ring(tx, ty, std::max(3.0f, d.radius * 0.13f), 1.5f, rgb8(10, 20, 60));
    const int scale = text_scale(layout);
    std::string what = state.topback > 0.04 ? "follow" : state.topback < -0.04 ? "draw" : "";
    const char *english = state.side > 0.04 ? "right" : state.side < -0.04 ? "left" : "";
    if (*english) what += (what.empty() ? "" : " + ") + std::string(english) + (what.empty() ? " english" : "");
    const std::string label = "Spin: " + (what.empty() ? std::string("centre") : what);
    const int w = text_width(label, scale);
    draw_text(canvas, label, static_cast<int>(d.cx) - w - static_cast<int>(d.radius * 1.2f),
              static_cast<int>(d.cy + d.radius) - text_height(scale), TextStyle{scale, kDim, false});
    // the cue's elevation beside the dial, above the spin's name
    char elevation[48];
    std::snprintf(elevation, sizeof elevation, "Cue %2.0f deg%s", state.elevation,
                  state.elevation >= 60 ? " masse" : state.elevation > 0 ? " swerve" : " level");
    const int ew = text_width(elevation, scale);
    draw_text(canvas, elevation, static_cast<int>(d.cx) - ew - static_cast<int>(d.radius * 1.2f),
              static_cast<int>(d.cy + d.radius) - 2 * text_height(scale) - scale * 4, TextStyle{scale, kDim, false});
}

void draw_status(Canvas &canvas, const Screen &layout, const PanelState &state) {
    const int scale = text_scale(layout);
    const float p = pad(layout);
    const int left = static_cast<int>(layout.panel.x + p * 1.5f);
    const int max_w = static_cast<int>(meter_rect(layout).x - layout.panel.x - 3 * p);
    int s = scale;  // one size for all the lines: the largest at which each fits
    for (const std::string &line : state.lines) s = std::min(s, fit_scale(line, max_w, scale));
    int y = static_cast<int>(layout.panel.y + p);
    for (const std::string &line : state.lines) {
        draw_text(canvas, line, left, y, TextStyle{s, kText, false});
        y += kLineAdvance * s;
    }
    const float r = layout.panel.h * 0.085f;
    const float cy = layout.panel.y + layout.panel.h - p - r;
    float x = static_cast<float>(left) + r;
    for (int number : state.pocketed) {
        if (x + r > static_cast<float>(left + max_w)) break;
        draw_ball(canvas, x, cy, r, number, rest_pose(number));
        x += 2.3f * r;
    }
}

}  // namespace

Dial spin_dial(const Screen &layout) {
    const float r = layout.panel.h * 0.36f;
    return {layout.panel.x + layout.panel.w - pad(layout) * 2 - r, layout.panel.y + layout.panel.h * 0.5f, r};
}

void clamp_offset(double &side, double &topback) {
    const double r = std::hypot(side, topback);
    if (r > kMiscueLimit) side *= kMiscueLimit / r, topback *= kMiscueLimit / r;
}

bool dial_offset(const Dial &dial, float x, float y, double &side, double &topback) {
    const double dx = (x - dial.cx) / dial.radius, dy = -(y - dial.cy) / dial.radius;
    if (std::hypot(dx, dy) > 1.0) return false;
    side = dx;
    topback = dy;
    clamp_offset(side, topback);
    return true;
}

void draw_panel_base(Canvas &canvas, const Screen &layout) {
    if (layout.panel.h <= 0) return;
    const RectF &p = layout.panel;
    canvas.fill_rect(p.x, p.y, p.x + p.w, p.y + p.h, kPanel);
    canvas.fill_rect(p.x, p.y, p.x + p.w, p.y + 2, rgb8(60, 40, 25));
    const RectF r = meter_rect(layout);
    canvas.fill_rect(r.x - 2, r.y - 2, r.x + r.w + 2, r.y + r.h + 2, rgb8(70, 70, 74));
    canvas.fill_rect(r.x, r.y, r.x + r.w, r.y + r.h, rgb8(10, 10, 12));
    // the spin selector: a cue ball seen from behind the cue, the miscue limit
    const Dial d = spin_dial(layout);
    const Mat3 facing = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    draw_ball(canvas, d.cx, d.cy, d.radius, -1, facing);
    canvas.ring(d.cx, d.cy, d.radius * static_cast<float>(kMiscueLimit), 1.2f, rgb8(60, 60, 60), 0.7f);
    canvas.line({d.cx - d.radius * 0.9f, d.cy}, {d.cx + d.radius * 0.9f, d.cy}, 1, rgb8(90, 90, 90), 0.5f);
    canvas.line({d.cx, d.cy - d.radius * 0.9f}, {d.cx, d.cy + d.radius * 0.9f}, 1, rgb8(90, 90, 90), 0.5f);
}

void draw_panel(Canvas &canvas, const Screen &layout, const PanelState &state) {
    if (layout.panel.h <= 0) return;
    draw_status(canvas, layout, state);
    draw_meter(canvas, layout, state);
    draw_dial(canvas, layout, state);
}

void draw_help(Canvas &canvas, const Screen &layout, const std::string &title, const std::vector<std::string> &lines) {
    const RectF &t = layout.table;
    size_t longest = title.size();
    for (const std::string &l : lines) longest = std::max(longest, l.size());
    // Above the centre line's balls: the box with its margins fits in the
    // table's upper 40 % (the rack reaches 2 diameters, 9 % of the width,
    // either side of the centre line; the head spot's cue ball is on it).
    int scale = text_scale(layout);
    const int max_w = static_cast<int>(t.w * 0.8f);
    while (scale > 1 && (text_width(std::string(longest, 'M'), scale) > max_w ||
                         static_cast<float>((static_cast<int>(lines.size()) + 3.5f) * kLineAdvance * scale) > t.h * 0.4f))
        --scale;
    const int w = text_width(std::string(longest, 'M'), scale), line_h = kLineAdvance * scale;
    const int h = (static_cast<int>(lines.size()) + 2) * line_h;
    const float margin = static_cast<float>(line_h);
    const float x0 = t.x + (t.w - static_cast<float>(w)) / 2, y0 = t.y + t.h * 0.4f - static_cast<float>(h) - margin * 0.5f;
    canvas.fill_rect(x0 - margin, y0 - margin, x0 + static_cast<float>(w) + margin, y0 + static_cast<float>(h) + margin * 0.5f,
                     {0, 0, 0}, 0.72f);
    draw_text(canvas, title, static_cast<int>(x0), static_cast<int>(y0), TextStyle{scale, rgb8(255, 225, 120), true});
    int y = static_cast<int>(y0) + 2 * line_h;
    for (const std::string &l : lines) {
        draw_text(canvas, l, static_cast<int>(x0), y, TextStyle{scale, kText, true});
        y += line_h;
    }
}

void draw_banner(Canvas &canvas, const Screen &layout, const std::string &text) {
    const RectF &t = layout.table;
    const int max_w = static_cast<int>(t.w * 0.8f);
    // as large as it goes on at most three lines
    int scale = text_scale(layout) * 2;
    std::vector<std::string> lines = wrap(text, max_w, scale);
    const auto fits = [&]() {
        if (lines.size() > 3) return false;
        for (const std::string &l : lines)
            if (text_width(l, scale) > max_w) return false;
        return true;
    };
    while (scale > 1 && !fits()) lines = wrap(text, max_w, --scale);
    const int line_h = kLineAdvance * scale, h = static_cast<int>(lines.size()) * line_h;
    int widest = 0;
    for (const std::string &l : lines) widest = std::max(widest, text_width(l, scale));
    const float cx = t.x + t.w / 2, y0 = t.y + (t.h - static_cast<float>(h)) / 2;
    const float m = static_cast<float>(line_h) * 0.6f;
    canvas.fill_rect(cx - static_cast<float>(widest) / 2 - m, y0 - m, cx + static_cast<float>(widest) / 2 + m,
                     y0 + static_cast<float>(h) + m * 0.5f, {0, 0, 0}, 0.65f);
    int y = static_cast<int>(y0);
    for (const std::string &l : lines) {
        draw_text(canvas, l, static_cast<int>(cx) - text_width(l, scale) / 2, y, TextStyle{scale, rgb8(255, 235, 140), true});
        y += line_h;
    }
}

void draw_corner_text(Canvas &canvas, const Screen &layout, const std::string &text) {
    const int scale = fit_scale(text, static_cast<int>(layout.table.w * 0.9f), text_scale(layout));
    draw_text(canvas, text, static_cast<int>(layout.table.x) + 3 * scale, static_cast<int>(layout.table.y) + 3 * scale,
              TextStyle{scale, kText, true});
}

}  // namespace demo
