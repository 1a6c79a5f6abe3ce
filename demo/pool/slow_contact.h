/* SPDX-License-Identifier: MIT */
// slow_contact.h - what the world engine does with contacts too slow for an
// impulse (Model::absorb_below): velocities limited so as to approach
// nothing a ball touches, and slides ended at once.  Pure functions of a
// ball's state; the engine finds the contacts.
#ifndef C2D_DEMO_SLOW_CONTACT_H
#define C2D_DEMO_SLOW_CONTACT_H

#include <vector>

#include "pool/motion.h"

namespace demo {

// Velocity limits hold to this: an approach slower is of rounding size.
constexpr double kGraze = 1e-12;  // m/s

// A velocity constraint v.n <= c: not approaching a contact along n (unit,
// towards it) faster than the contact moves away (c >= 0).
struct Limit {
    double nx, ny, c;
};

// (x, y) keeps every limit (to kGraze).
bool within(double x, double y, const std::vector<Limit> &limits);

// The velocity nearest (x, y) that approaches none of the contacts: the
// point of the convex set within(...) closest to it, in the plane either
// (x, y) itself, its projection on one limit's line, or the crossing of
// two.  The set holds 0 (every c >= 0), so the nearest point is never
// longer than (x, y): the energy only decreases.
void nearest_within(double &x, double &y, const std::vector<Limit> &limits);

// Same velocities and spins.
bool same_motion(const Ball &a, const Ball &b);

// A sliding ball as its slide would leave it: the slip u shrinks to 0 along
// its direction, taking 2/7 of it from v (motion.h), and the ball rolls.
// The slide's friction does only negative work, so the energy drops.
Ball slid(Ball b);

}  // namespace demo

#endif
