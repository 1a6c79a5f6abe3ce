// model.h - the physical parameters an engine works with (SimConfig in
// sim.h sets them; their values and sources are there).
#ifndef C2D_DEMO_MODEL_H
#define C2D_DEMO_MODEL_H

#include "motion.h"

namespace demo {

// An impact's surface: restitution e (normal), Coulomb friction mu, and the
// tangential restitution beta of Walton's rough-disk model (c2d_surface).
struct Surface {
    double restitution, friction, tangential_restitution;
};

struct Model {
    // false: the frictionless scenes.  Balls move straight at constant
    // velocity, never spin, and impacts are smooth (c2d_collide,
    // c2d_collide_normal, c2d_time_of_impact).
    bool friction;
    Cloth cloth;
    Surface ball;      // ball-ball
    Surface cushion;   // ball-cushion, jaw facings and noses
    // Impacts whose approach speed along the normal is below this are
    // elastic (e = 1; friction as usual).  Restitution rises towards 1 at low
    // speed in real (viscoelastic) contacts; here it stops a ball that its
    // own spin drives into a cushion or another ball from bouncing ever
    // shorter (infinitely many impacts in a finite time: inelastic collapse,
    // treated as Luding & McNamara's TC model does).
    double elastic_below;  // m/s
};

}  // namespace demo

#endif
