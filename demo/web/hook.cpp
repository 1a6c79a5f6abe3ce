/* SPDX-License-Identifier: MIT */
// hook.cpp - the browser build's entry points for the page's
// window.collide2d (demo/web/shell.html): the game's state and shots, for
// tests and tools.  Each is a C function the page calls through cwrap, on
// the game play_window runs (app/controller.h playing_game).
#include <emscripten.h>

#include <cstdio>
#include <string>

#include "app/controller.h"
#include "pool/sim.h"

extern "C" {

// {"balls":[{"number":N,"x":X,"y":Y,"on_table":B},...]}: the balls in the
// engine's order, metres, each coordinate with 17 significant digits (the
// double itself, as the native --json writes it); "{}" before the game runs.
// The string lives until the next call.
EMSCRIPTEN_KEEPALIVE const char *c2d_web_state() {
    static std::string json;
    const demo::PlayingGame *game = demo::playing_game();
    if (!game) return "{}";
    json = "{\"balls\":[";
    char item[160];
    bool first = true;
    for (const demo::Ball &b : game->simulation().balls()) {
        std::snprintf(item, sizeof item, "%s{\"number\":%d,\"x\":%.17g,\"y\":%.17g,\"on_table\":%s}", first ? "" : ",",
                      b.number, b.x, b.y, b.active ? "true" : "false");
        json += item;
        first = false;
    }
    json += "]}";
    return json.c_str();
}

// 1 when the shot was played (see PlayingGame::shoot), 0 otherwise.
EMSCRIPTEN_KEEPALIVE int c2d_web_shoot(double angle_deg, double speed, double side, double topback) {
    demo::PlayingGame *game = demo::playing_game();
    return game && game->shoot(demo::Shot{angle_deg, speed, side, topback}) ? 1 : 0;
}

// 1 when every ball on the table is still.
EMSCRIPTEN_KEEPALIVE int c2d_web_at_rest() {
    const demo::PlayingGame *game = demo::playing_game();
    return game && game->simulation().at_rest() ? 1 : 0;
}

// Frames drawn so far (the page's frame rate: two readings over a time).
EMSCRIPTEN_KEEPALIVE double c2d_web_frames() {
    const demo::PlayingGame *game = demo::playing_game();
    return game ? static_cast<double>(game->frames_drawn()) : 0;
}

}  // extern "C"
