/* SPDX-License-Identifier: MIT */
// draw_balls.h - pool balls as lit spheres: the standard colours, stripes
// (9-15), the number in its white circle, a soft shadow; each ball turned by
// its own orientation, integrated from its angular velocity frame by frame,
// so stripes and numbers roll with the ball.  The gas scene's disks are
// coloured by speed instead.
#ifndef C2D_DEMO_DRAW_BALLS_H
#define C2D_DEMO_DRAW_BALLS_H

#include <vector>

#include "app/canvas.h"
#include "app/view.h"
#include "pool/scene.h"

namespace demo {

// A rotation: body coordinates to world (columns are the body axes).
struct Mat3 {
    double m[3][3];
};

// One orientation per ball.  The body's x axis carries the number circles
// (at +x and -x), its z axis is the stripe's axis.
class BallPoses {
public:
    // Every ball at rest in its racked pose: number up, a little tilted.
    void reset(const std::vector<Ball> &balls);
    // Turns each ball on the table by its angular velocity (wx, wy, wz, held
    // over the frame) over dt.
    void advance(const std::vector<Ball> &balls, double dt);
    Mat3 pose(size_t i) const;

private:
    std::vector<Mat3> poses_;
};

// The racked pose of ball number n (also for screenshots without history).
Mat3 rest_pose(int number);

// A ball of the given number (0 = cue) centred at (cx, cy), radius in pixels.
void draw_ball(Canvas &canvas, float cx, float cy, float radius, int number, const Mat3 &pose);

// A ball dropping into the hole at (hx, hy): progress 0 where it fell (x, y),
// 1 gone (smaller, darker, nearer the hole's centre).
void draw_falling(Canvas &canvas, const View &view, double x, double y, double hx, double hy, int number,
                  const Mat3 &pose, double progress);

// Shadows, then the balls on the table.
void draw_balls(Canvas &canvas, const View &view, const std::vector<Ball> &balls, const BallPoses &poses);

// The gas: flat disks from blue (slow) to red (twice the mean speed).
void draw_gas(Canvas &canvas, const View &view, const std::vector<Ball> &balls, double mean_speed);

}  // namespace demo

#endif
