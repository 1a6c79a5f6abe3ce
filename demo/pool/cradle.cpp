/* SPDX-License-Identifier: MIT */
// cradle.cpp - see cradle.h.  Between events a lossless ball keeps its
// velocity, so the velocities after the last event of each ball are the
// balls' velocities at any later moment until the next event: the events
// alone carry the outcome, at the exact moment it is taken.
#include "pool/cradle.h"

#include <cmath>

#include "pool/det_math.h"

namespace demo {

CradleCheck::CradleCheck(const std::vector<Ball> &balls) : velocity_(2 * balls.size(), 0.0) {
    for (size_t i = 0; i < balls.size(); ++i) {
        velocity_[2 * i] = balls[i].vx;
        velocity_[2 * i + 1] = balls[i].vy;
    }
}

void CradleCheck::frame(const std::vector<Event> &events) {
    for (const Event &e : events) {
        if (crossed_) return;
        if (e.kind == EventKind::Strike && !struck_) {
            struck_ = true;
            strike_vx_ = e.vx, strike_vy_ = e.vy;
        } else if (e.kind != EventKind::BallBall && e.kind != EventKind::Strike) {
            crossed_ = struck_;
            if (crossed_) return;
        }
        // a ball-ball impact is two records, one a ball: one impact
        if (e.kind == EventKind::BallBall && e.ball < e.other) ++impacts_;
        velocity_[2 * static_cast<size_t>(e.ball)] = e.vx;
        velocity_[2 * static_cast<size_t>(e.ball) + 1] = e.vy;
    }
}

CradleOutcome CradleCheck::outcome() const {
    CradleOutcome o;
    const size_t balls = velocity_.size() / 2;
    o.row = static_cast<int>(balls) - 1;
    o.head_on = struck_ && strike_vx_ > 0 && strike_vy_ == 0;
    o.crossed = crossed_;
    o.speed = det_hypot(strike_vx_, strike_vy_);
    o.impacts = impacts_;
    o.minimal_impacts = o.row;
    o.actual = velocity_;
    o.expected.assign(velocity_.size(), 0.0);
    o.expected[2 * (balls - 1)] = strike_vx_;
    o.expected[2 * (balls - 1) + 1] = strike_vy_;
    o.exact = o.head_on && o.crossed && o.impacts == o.minimal_impacts;
    for (size_t k = 0; k < velocity_.size(); ++k)
        o.exact = o.exact && o.actual[k] == o.expected[k];  // -0 is standing still too
    return o;
}

}  // namespace demo
