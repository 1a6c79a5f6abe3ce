/* SPDX-License-Identifier: MIT */
// render.h - the demo's pictures and the game in a window: frames are drawn
// in software (canvas.h) and shown through one SDL texture, so an offscreen
// screenshot (no display needed), a window's screenshot and what the player
// sees are the same drawing.
#ifndef C2D_DEMO_RENDER_H
#define C2D_DEMO_RENDER_H

#include <string>

#include "game/game.h"
#include "pool/sim.h"

namespace demo {

enum class WindowResult { Ok, Unavailable, Failed };

// The final frame, drawn offscreen into a PNG.
bool screenshot_offscreen(const Simulation &sim, const std::string &path, std::string &error);

// Opens a real window, draws the frame there and saves what the window's
// renderer drew.  Unavailable: no display, or no window/renderer.
WindowResult screenshot_window(const Simulation &sim, const std::string &path, std::string &error);

// The game (keys in the help box it opens with, H toggles it): aim with the
// mouse, press and drag to pull the cue back, release to shoot; spin on the
// panel's cue-ball diagram or the arrow keys.  Unavailable (with the reason
// in error) when there is no display or no window/renderer can be made.
WindowResult play_window(const SimConfig &config, const Players &players, std::string &error);

}  // namespace demo

#endif
