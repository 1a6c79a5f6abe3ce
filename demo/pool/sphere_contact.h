/* SPDX-License-Identifier: MIT */
// sphere_contact.h - the pool scenes' impacts, ball-ball and ball-rail, in
// the model the run chose (Model::contact): balls as spheres with their
// 3-D spin (the library's c2d_collide_balls and c2d_collide_cushion), or
// the former disks in the plane of the centres (c2d_collide_rough,
// c2d_collide_rough_normal).  Pure functions of the balls' states at the
// contact; the engine finds the contacts and the world's effective
// restitution (its collapse rule), which these take as given.
//
// The sphere models (sources and figures in docs/POOL.md):
//   ball-ball  contact at the equator; Newton's restitution on the normal
//              approach, Coulomb friction against the full slip of the
//              contact points (horizontal from the velocities and wz,
//              vertical from top and back spin), sliding through the impact
//              or stopping; the cloth takes the vertical part of the
//              impulse.  Friction constant (Model::ball.friction) or
//              Alciatore's mu(v) = a + b exp(-c v) of the sliding speed
//              (technical proof A.14's fit for phenolic balls).
//   cushion    the nose touches the ball at Model::cushion_height above
//              the cloth (the normal tilted down by asin(h/R - 1)): part of
//              the impulse presses the ball into the cloth, and the rail's
//              friction acts on the slip there, taking topspin away (Han
//              2005's closed form, friction along the slip).  A jaw's
//              facing is a cushion along its line, a jaw's nose a cushion
//              whose normal points from the ball to the nose's axis.
// The world's faces stay where they are (a ball touches one when its
// centre is R from the line): the nose's height changes the impulse, not
// where the impact happens.
#ifndef C2D_DEMO_SPHERE_CONTACT_H
#define C2D_DEMO_SPHERE_CONTACT_H

#include "pool/model.h"
#include "pool/motion.h"

namespace demo {

// Alciatore's fit of ball-ball friction against sliding speed (SI units):
// mu(v) = kAlciatoreA + kAlciatoreB exp(-kAlciatoreC v).
constexpr double kAlciatoreA = 9.951e-3, kAlciatoreB = 0.108, kAlciatoreC = 1.088;

// Each function takes the balls' states at the contact (spins included)
// and writes their velocities and spins after it; false (nothing written)
// when the library finds no impact to resolve (a graze, or separating by
// rounding): the world's own rule then.  The motion state is left to the
// caller.
//   collide_balls      a and b touching, the normal from a's centre to b's
//   collide_face       an immovable face; (nx, ny) unit, from the ball to it
//   collide_nose       a jaw's nose: a vertical cylinder of radius r at (x, y)
bool collide_balls(const Model &model, double restitution, Ball &a, Ball &b);
bool collide_face(const Model &model, double restitution, Ball &a, double nx, double ny);
bool collide_nose(const Model &model, double restitution, Ball &a, double x, double y, double r);

}  // namespace demo

#endif
