/* SPDX-License-Identifier: MIT */
// aim.h - the aiming aids: where the cue ball's straight path first meets a
// ball, a cushion, a jaw or a pocket (the ghost ball), the object ball's
// direction along the line of centres and the cue ball's tangent line (the
// stun shot's two paths, lengths in proportion to their speeds), and the cue
// stick, drawn behind the cue ball and pulled back with the power.
#ifndef C2D_DEMO_AIM_H
#define C2D_DEMO_AIM_H

#include <vector>

#include "app/canvas.h"
#include "app/engine_view.h"
#include "app/view.h"

namespace demo {

struct AimHit {
    enum Kind { Nothing, Ball, Cushion, Pocket } kind = Nothing;
    double distance = 0;  // the moving ball's travel to the contact, m
    double x = 0, y = 0;  // its centre at the contact (the ghost ball)
    int ball = -1;        // Ball: the index of the ball hit; Pocket: the pocket
    double nx = 0, ny = 0;  // Ball: unit line of centres; Cushion: the face's normal
};

// The first thing a ball at (x, y) moving along (dx, dy) (unit) would meet,
// going straight, within max_distance; `moving` is its index (skipped).
AimHit first_contact(const TableShape &table, const std::vector<Ball> &balls, int moving, double x, double y,
                     double dx, double dy, double max_distance);

struct AimState {
    double angle = 0;   // radians, 0 = +x, counter-clockwise
    double power = 0;   // 0..1 of the greatest speed
    double side = 0, topback = 0;  // tip offset, fractions of R
    double elevation = 0;          // the cue's elevation, degrees in [0, kMaxElevation]
};

// Ghost ball and lines, then the cue stick, for the cue ball (index 0).
void draw_aim(Canvas &canvas, const View &view, const TableShape &table, const std::vector<Ball> &balls,
              const AimState &aim);

}  // namespace demo

#endif
