/* SPDX-License-Identifier: MIT */
// model.h - the physical parameters an engine works with (SimConfig in
// sim.h sets them; their values and sources are there).
#ifndef C2D_DEMO_MODEL_H
#define C2D_DEMO_MODEL_H

#include "pool/motion.h"

namespace demo {

// An impact's surface: restitution e (normal), Coulomb friction mu, and the
// tangential restitution beta of Walton's rough-disk model (c2d_surface).
struct Surface {
    double restitution, friction, tangential_restitution;
};

// The contact model of the pool scenes' impacts (sphere_contact.h):
//   Sphere           balls as spheres (c2d_collide_balls, c2d_collide_cushion):
//                    friction on the full 3-D slip (top and back spin
//                    included), the cushion's nose above the centre; the
//                    ball-ball friction constant (Surface::friction)
//   SphereAlciatore  the same with Alciatore's speed-dependent ball-ball
//                    friction mu(v) = a + b exp(-c v) (kAlciatore*)
//   Disk             the former model: disks in the plane of the centres
//                    (c2d_collide_rough, c2d_collide_rough_normal), wx and
//                    wy untouched by an impact
enum class ContactModel { Sphere, SphereAlciatore, Disk };
// --model's name of each: sphere, sphere-alciatore, disk.
inline const char *contact_model_name(ContactModel c) {
    return c == ContactModel::Sphere ? "sphere" : c == ContactModel::SphereAlciatore ? "sphere-alciatore" : "disk";
}

struct Model {
    // false: the frictionless scenes.  Balls move straight at constant
    // velocity, never spin, and impacts are smooth (c2d_collide,
    // c2d_collide_normal, c2d_time_of_impact).
    bool friction;
    Cloth cloth;
    Surface ball;      // ball-ball
    Surface cushion;   // ball-cushion, jaw facings and noses
    // Slow contacts.  An impulse model has no resting contact: a ball that
    // its own spin, or the friction of its slide, presses into a cushion or
    // a touching ball would bounce ever shorter, infinitely many impacts in
    // a finite time (inelastic collapse).  So a contact approaching slower
    // than this along the normal is absorbed instead of bounced: each ball
    // takes the nearest velocity that heads into none of the things it
    // touches (and the same for the rolling velocity R (wy, -wx) its spin
    // pulls it towards, or it rolls if it spins at least that fast); one
    // left slower than this stops.  If the pair's accelerations still press
    // them together (a sustained contact), the balls in contact end their
    // slides at once (the state each slide would end in), and if that is not
    // enough they move on as one, at their mean velocity, rolling.  All of it
    // only takes energy away; what it changes is small (a 5 mm/s nudge would
    // move a ball at most 0.13 mm; clusters pushed slowly move together).
    double absorb_below;  // m/s
    ContactModel contact = ContactModel::Sphere;
    // The cushion nose's height above the cloth, m (the sphere models):
    // 0.64 D (sim.h gives the sources).
    double cushion_height = 1.28 * kBallRadius;
    // The cue's end mass, kg, that the strike's squirt comes from (motion.h:
    // kCueEndMass, m / 30 as pooltool's default; --cue-end-mass).
    double cue_end_mass = kCueEndMass;
};

}  // namespace demo

#endif
