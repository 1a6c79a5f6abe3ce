/* SPDX-License-Identifier: MIT */
// hud.h - what the window shows around the table: the panel under it
// (status lines, the balls pocketed so far, the power meter and the spin
// selector: a cue-ball diagram with the miscue limit and the tip's
// position), the help box and the banner for messages (end of a game).
// Text is fitted and wrapped to stay inside the window.
#ifndef C2D_DEMO_HUD_H
#define C2D_DEMO_HUD_H

#include <string>
#include <vector>

#include "app/canvas.h"
#include "app/view.h"
#include "pool/sim.h"

namespace demo {

constexpr double kMiscueLimit = kMaxTipOffset;  // the cue tip's farthest offset, fraction of R (sim.h)

struct PanelState {
    std::vector<std::string> lines;  // status, top to bottom
    std::vector<int> pocketed;       // numbers of the object balls off the table
    double power = 0;                // 0..1
    double max_speed = 0;            // m/s at full power
    double side = 0, topback = 0;    // tip offset, fractions of R
    double elevation = 0;            // the cue's elevation, degrees
};

// The spin selector's circle in the panel (for mouse clicks).
struct Dial {
    float cx, cy, radius;
};
Dial spin_dial(const Screen &layout);

// The tip offset under the canvas point (x, y), clamped to the miscue limit;
// false if (x, y) is not on the dial.
bool dial_offset(const Dial &dial, float x, float y, double &side, double &topback);

// Clamps (side, topback) into the miscue limit's circle.
void clamp_offset(double &side, double &topback);

// What does not change: the panel's ground, the meter's frame, the dial's
// ball and its marks (drawn once, under every frame's draw_panel).
void draw_panel_base(Canvas &canvas, const Screen &layout);
void draw_panel(Canvas &canvas, const Screen &layout, const PanelState &state);

// A translucent box over the table with a title and lines of text.
void draw_help(Canvas &canvas, const Screen &layout, const std::string &title, const std::vector<std::string> &lines);

// A message across the middle of the table, wrapped to fit.
void draw_banner(Canvas &canvas, const Screen &layout, const std::string &text);

// A short line at the top left of the table (the gas scene's figures).
void draw_corner_text(Canvas &canvas, const Screen &layout, const std::string &text);

}  // namespace demo

#endif
