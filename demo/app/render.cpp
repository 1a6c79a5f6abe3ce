/* SPDX-License-Identifier: MIT */
// render.cpp - see render.h and window.h.  A frame: the cached table
// (redrawn only when the window's size changes), the balls, the aiming aids,
// the panel, then the help box or a banner.
#include "app/render.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "app/aim.h"
#include "app/canvas.h"
#include "app/draw_balls.h"
#include "app/draw_table.h"
#include "app/engine_view.h"
#include "app/hud.h"
#include "app/png.h"
#include "app/view.h"
#include "app/window.h"

namespace demo {

namespace {

const char *const kHelp[] = {
    "Mouse             aim (the ghost ball shows the first contact)",
    "Shift + mouse     fine aim;   , and .  turn the aim a little",
    "Left drag         pull the cue back (power); release to shoot",
    "Right button      cancel the stroke",
    "Arrow keys        tip offset: up follow, down draw, sides english",
    "Click the ball    set the tip offset; C centre; wheel follow/draw",
    "PgUp / PgDn       raise / lower the cue 5 deg (swerve, masse); L level",
    "8-ball: ball in hand - move the mouse, click to put the cue ball down",
    "M mute   H help   F12 screenshot   R rack again   Esc quit",
};

// The canvas size that fits the table (and panel) into max_w x max_h.
void fit_size(const Simulation &sim, int max_w, int max_h, int &width, int &height) {
    const TableShape t = table_shape(sim.table());
    Screen::fit(t.length, t.width, t.rail, pool(sim), max_w, max_h, width, height);
}

// A picture without a player: the balls at rest poses, the run's figures.
Overlay still_overlay(const Simulation &sim) {
    Overlay o;
    const Stats &s = sim.stats();
    char line[160];
    std::snprintf(line, sizeof line, "%.1f s simulated   %ld ball-ball and %ld cushion contacts", s.sim_seconds,
                  s.ball_ball_collisions, s.cushion_collisions);
    o.panel.lines.emplace_back(line);
    std::snprintf(line, sizeof line, "%d balls on the table   tunnelled %ld", sim.object_balls_left(), s.tunnelled);
    o.panel.lines.emplace_back(line);
    o.panel.pocketed = pocketed_numbers(sim);
    o.panel.max_speed = kMaxPlaySpeed;
    return o;
}

void draw_still(Canvas &frame, const Simulation &sim, const Screen &layout, const Overlay &overlay) {
    const TableShape shape = table_shape(sim.table());
    BallPoses poses;
    poses.reset(sim.balls());
    Backdrop backdrop;
    draw_frame(frame, backdrop.get(sim, shape, layout), layout, sim, shape, poses, overlay);
}

void draw_still(Canvas &frame, const Simulation &sim, const Screen &layout) { draw_still(frame, sim, layout, still_overlay(sim)); }

// Without DISPLAY or WAYLAND_DISPLAY SDL is not asked at all (it would print
// its own complaints about XDG_RUNTIME_DIR before ours), unless the user
// chose a video driver.
bool have_display(std::string &reason) {
    const auto set = [](const char *name) {
        const char *v = std::getenv(name);
        return v && *v;
    };
    if (!set("DISPLAY") && !set("WAYLAND_DISPLAY") && !set("SDL_VIDEODRIVER")) {
        reason = "no display (neither DISPLAY nor WAYLAND_DISPLAY is set)";
        return false;
    }
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
        reason = std::string("no display: ") + SDL_GetError();
        return false;
    }
    const char *driver = SDL_GetCurrentVideoDriver();
    if (!driver || !std::strcmp(driver, "offscreen") || !std::strcmp(driver, "dummy")) {
        reason = std::string("no display (SDL video driver '") + (driver ? driver : "none") + "')";
        SDL_Quit();
        return false;
    }
    return true;
}

}  // namespace

bool pool(const Simulation &sim) { return sim.config().scene != Scene::Gas; }

Screen layout_for(const Simulation &sim, int width, int height) {
    const TableShape t = table_shape(sim.table());
    return Screen(width, height, t.length, t.width, t.rail, pool(sim));
}

void draw_frame(Canvas &frame, const Canvas &backdrop, const Screen &layout, const Simulation &sim, const TableShape &shape,
                const BallPoses &poses, const Overlay &overlay) {
    frame.pixels() = backdrop.pixels();
    if (!pool(sim)) {
        const double mean = std::sqrt(2 * sim.energy() / (kBallMass * std::max(1, sim.balls_total())));
        draw_gas(frame, layout.view, sim.balls(), mean);
        char text[128];
        std::snprintf(text, sizeof text, "%d disks   t = %.1f s   tunnelled %ld", sim.balls_total(), sim.stats().sim_seconds,
                      sim.stats().tunnelled);
        draw_corner_text(frame, layout, text);
        return;
    }
    for (const Drop &d : overlay.drops)
        draw_falling(frame, layout.view, d.x, d.y, d.hole_x, d.hole_y, d.number, d.pose, d.age / kDropSeconds);
    draw_balls(frame, layout.view, sim.balls(), poses);
    if (overlay.aiming) draw_aim(frame, layout.view, shape, sim.balls(), overlay.aim);
    // the panel's rows as the backdrop has them: a cue drawn back over the
    // panel (a long stroke from near the head rail) goes under it
    if (overlay.aiming && layout.panel.h > 0) {
        const int y0 = std::max(0, static_cast<int>(layout.panel.y)), w = frame.width();
        const int y1 = std::min(frame.height(), static_cast<int>(std::ceil(layout.panel.y + layout.panel.h)));
        if (y0 < y1 && frame.pixels().size() == backdrop.pixels().size())
            std::copy(backdrop.pixels().begin() + static_cast<long>(y0) * w, backdrop.pixels().begin() + static_cast<long>(y1) * w,
                      frame.pixels().begin() + static_cast<long>(y0) * w);
    }
    draw_panel(frame, layout, overlay.panel);
    if (overlay.help) draw_help(frame, layout, "collide2d billiards - keys", std::vector<std::string>(std::begin(kHelp), std::end(kHelp)));
    else if (!overlay.banner.empty()) draw_banner(frame, layout, overlay.banner);
}

std::vector<int> pocketed_numbers(const Simulation &sim) {
    std::vector<int> numbers;
    for (const Ball &b : sim.balls())
        if (!b.active && b.number != 0) numbers.push_back(b.number);
    return numbers;
}

// A window that fits the display's usable area (less room for its frame),
// resizable; the frame keeps the table's aspect with black bars.
WindowResult open_window(const Simulation &sim, Window &w, std::string &error) {
    if (!have_display(error)) return WindowResult::Unavailable;
    SDL_Rect usable{0, 0, kDefaultWidth, kDefaultWidth};
    if (SDL_GetDisplayUsableBounds(0, &usable) != 0 || usable.w <= 0 || usable.h <= 0) usable = {0, 0, kDefaultWidth, 900};
    int width = 0, height = 0;
    fit_size(sim, std::min(kDefaultWidth * 2, usable.w * 92 / 100), usable.h * 88 / 100, width, height);
    w.window = SDL_CreateWindow("collide2d billiards", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height,
                                SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    if (!w.window) {
        error = std::string("cannot create window: ") + SDL_GetError();
        return WindowResult::Unavailable;
    }
    w.renderer = SDL_CreateRenderer(w.window, -1, SDL_RENDERER_ACCELERATED | SDL_RENDERER_PRESENTVSYNC);
    if (!w.renderer) w.renderer = SDL_CreateRenderer(w.window, -1, SDL_RENDERER_SOFTWARE);
    if (!w.renderer) {
        error = std::string("cannot create renderer: ") + SDL_GetError();
        return WindowResult::Unavailable;
    }
    w.texture_w = width;
    w.texture_h = height;
    SDL_SetRenderDrawColor(w.renderer, 0, 0, 0, 255);
    return WindowResult::Ok;
}

bool screenshot_offscreen(const Simulation &sim, const std::string &path, std::string &error) {
    int width = 0, height = 0;
    fit_size(sim, kDefaultWidth, kDefaultWidth, width, height);
    Canvas frame(width, height);
    draw_still(frame, sim, layout_for(sim, width, height));
    return write_png(path, width, height, frame.rgb(), error);
}

bool screenshot_offscreen(const Simulation &sim, const std::string &path, std::string &error,
                          const std::vector<std::string> &panel_lines, const std::vector<int> &pocketed) {
    int width = 0, height = 0;
    fit_size(sim, kDefaultWidth, kDefaultWidth, width, height);
    Canvas frame(width, height);
    Overlay o = still_overlay(sim);
    o.panel.lines = panel_lines;
    o.panel.pocketed = pocketed;
    draw_still(frame, sim, layout_for(sim, width, height), o);
    return write_png(path, width, height, frame.rgb(), error);
}

bool window_available(std::string &error) {
    if (!have_display(error)) return false;
    SDL_Quit();  // the screenshot opens its window again, after the run
    return true;
}

WindowResult screenshot_window(const Simulation &sim, const std::string &path, std::string &error) {
    Window w;
    const WindowResult opened = open_window(sim, w, error);
    if (opened != WindowResult::Ok) return opened;
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
    }
    int width = 0, height = 0;
    w.output_size(width, height);
    Canvas frame(width, height);
    draw_still(frame, sim, layout_for(sim, width, height));
    if (!w.show(frame)) {
        error = std::string("cannot draw in the window: ") + SDL_GetError();
        return WindowResult::Failed;
    }
    std::vector<uint8_t> rgb(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
    // read back what this window's renderer drew, before it is presented
    if (SDL_RenderReadPixels(w.renderer, nullptr, SDL_PIXELFORMAT_RGB24, rgb.data(), width * 3) != 0) {
        error = std::string("cannot read the window's pixels: ") + SDL_GetError();
        return WindowResult::Failed;
    }
    SDL_RenderPresent(w.renderer);
    return write_png(path, width, height, rgb, error) ? WindowResult::Ok : WindowResult::Failed;
}

}  // namespace demo
