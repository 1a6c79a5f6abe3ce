/* SPDX-License-Identifier: MIT */
// render.h - the demo's pictures: frames are drawn in software (canvas.h)
// and shown through one SDL texture, so an offscreen screenshot (no display
// needed), a window's screenshot and what the player sees (controller.h) are
// the same drawing.
#ifndef C2D_DEMO_RENDER_H
#define C2D_DEMO_RENDER_H

#include <string>
#include <vector>

#include "pool/sim.h"

namespace demo {

enum class WindowResult { Ok, Unavailable, Failed };

// The final frame, drawn offscreen into a PNG.
bool screenshot_offscreen(const Simulation &sim, const std::string &path, std::string &error);
// The same with the panel's lines and the tray's pocketed balls given (a
// game's: the players, the result), instead of the run's figures.
bool screenshot_offscreen(const Simulation &sim, const std::string &path, std::string &error,
                          const std::vector<std::string> &panel_lines, const std::vector<int> &pocketed);

// Whether a window can be opened (a display SDL can use), checked before a
// run that ends with screenshot_window; false with the reason in error.
bool window_available(std::string &error);

// Opens a real window, draws the frame there and saves what the window's
// renderer drew.  Unavailable: no display, or no window/renderer.
WindowResult screenshot_window(const Simulation &sim, const std::string &path, std::string &error);

}  // namespace demo

#endif
