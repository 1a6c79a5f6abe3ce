/* SPDX-License-Identifier: MIT */
// cradle.h - the check of the cradle scene against the textbook.  A cue
// ball at v head-on (along the row, +x) into N touching equal balls on a
// lossless, frictionless table: momentum and energy conservation in
// head-on impacts of equal masses at e = 1 swap the two velocities, so the
// pulse crosses the row gap by gap and the last ball leaves at v while the
// cue ball and the other N - 1 stand still.  N impacts are the fewest that
// can do it (each of the N gaps must carry the momentum across once), and
// exactly N happen when every swap is exact: a residual velocity of one
// ulp would leave a ball creeping into its neighbour, a further impact.
// The outcome is taken when the pulse has crossed: at the first event that
// is not a ball-ball impact (the last ball reaching the foot rail), or at
// the run's end if that comes first.
#ifndef C2D_DEMO_CRADLE_H
#define C2D_DEMO_CRADLE_H

#include <vector>

#include "pool/events.h"
#include "pool/motion.h"

namespace demo {

struct CradleOutcome {
    int row = 0;                   // N, the balls in the row
    bool head_on = false;          // the cue ball was struck along the row (+x, no y component)
    bool crossed = false;          // taken at the first cushion contact, not the run's end
    double speed = 0;              // the cue ball's speed after the strike, m/s
    long impacts = 0;              // ball-ball impacts until then
    long minimal_impacts = 0;      // N
    std::vector<double> expected;  // vx, vy of every ball (the cue ball first), textbook
    std::vector<double> actual;    // the same, as the engine left them
    // head-on, crossed, actual == expected exactly (no residual: -0 and 0
    // both stand still), impacts == N
    bool exact = false;
};

class CradleCheck {
public:
    // The balls as the scene set them up (at rest, the cue ball first).
    explicit CradleCheck(const std::vector<Ball> &balls);
    // A frame's events, in time order.
    void frame(const std::vector<Event> &events);
    CradleOutcome outcome() const;

private:
    std::vector<double> velocity_;  // vx, vy per ball, from the events
    double strike_vx_ = 0, strike_vy_ = 0;
    bool struck_ = false, crossed_ = false;
    long impacts_ = 0;
};

}  // namespace demo

#endif
