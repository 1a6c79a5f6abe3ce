// render.h - SDL2 drawing of a Simulation: offscreen screenshots (software
// renderer on a surface, no display needed), a window screenshot, and the
// interactive game.
#ifndef C2D_DEMO_RENDER_H
#define C2D_DEMO_RENDER_H

#include <string>

#include "sim.h"

namespace demo {

enum class WindowResult { Ok, Unavailable, Failed };

// The final frame rendered offscreen into a PNG.
bool screenshot_offscreen(const Simulation &sim, const std::string &path, std::string &error);

// Opens a real window, draws the frame there and saves what the window's
// renderer drew.  Unavailable: no display, or no window/renderer.
WindowResult screenshot_window(const Simulation &sim, const std::string &path, std::string &error);

// The game: aim with the mouse, drag for power, release to shoot; R re-racks,
// Esc quits.  Unavailable (with the reason in error) when there is no display
// or no window/renderer can be made.
WindowResult play_window(const SimConfig &config, std::string &error);

}  // namespace demo

#endif
