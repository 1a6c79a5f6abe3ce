/* SPDX-License-Identifier: MIT */
// motion.h - a ball on the cloth between events, in closed form, and the cue
// strike.  Sources: Leckie & Greenspan, "An event-driven pool simulation"
// (ICGA 2006); D. Alciatore, technical proofs TP 4.1-4.3 and A.4-A.5
// (billiards.colostate.edu); E. Kiefl, pooltool's documentation of the
// motion states.  The code is our own.
//
// Frame: x, y on the cloth, z up; the ball's centre is R above the cloth,
// its cloth contact point at -R z.  State: position p, velocity v, angular
// velocity w = (wx, wy, wz).  The contact point slips over the cloth at
//     u = v + w x (-R z) = (vx - R wy, vy + R wx).
//
//   sliding   u != 0.  Kinetic friction mu_s m g against u: a = -mu_s g u^,
//             and its torque (-R z) x F / I gives
//             dw_x/dt = -(5/2) mu_s g u^_y / R,  dw_y/dt = (5/2) mu_s g u^_x / R,
//             so du/dt = -(7/2) mu_s g u^: u shrinks along a fixed direction
//             and vanishes at t = 2|u0| / (7 mu_s g), when the ball rolls.
//             A ball struck in the centre (w = 0) slides 12 v0^2 /
//             (49 mu_s g) and leaves at 5/7 of v0.
//   rolling   u = 0, v != 0.  Rolling resistance: a = -mu_r g v^, with
//             w_xy = (-vy, vx) / R throughout; stops at t = |v0| / (mu_r g).
//   spinning  v = 0, wz != 0: turns in place.
//   stationary, pocketed.
// In every state on the cloth wz decays by spinning friction at
// 5 mu_sp g / (2R) rad/s^2 (the moment of a pressure spread over a small
// contact patch) until it reaches 0; that ends the spinning state and is
// clamped at 0 (no event) in the others, where wz does not move the ball.
// Between events each ball's position is therefore exactly quadratic in t.
//
// The strike (Leckie & Greenspan's cue model as pooltool codes it, with
// Alciatore's squirt, technical proof A.31).  The cue, raised by elev above
// the cloth, points along D = cos(elev) d - sin(elev) z (d the horizontal
// aim); the tip's offsets side and topback are fractions of R in the plane
// across the cue, so the tip meets the ball at
//     r = R (side e_right + topback e_up - sqrt(1 - side^2 - topback^2) D),
// e_right = d x z, e_up = sin(elev) d + cos(elev) z.  The impulse is
// J = P D_s, D_s the cue's direction turned about the vertical by the
// squirt angle a away from the side of the tip (right english squirts the
// ball left):
//     tan a = (5/2) s sqrt(1 - s^2) / (1 + m / m_e + (5/2)(1 - s^2)),
// s = side, m_e the cue's end mass (kCueEndMass): the tip's end mass is
// pushed aside by the offset contact, and the ball goes the other way
// (Alciatore, TP A.31; pooltool's squirt model).  The cloth takes the
// vertical part of J (a reaction through the centre, no moment: pooltool
// keeps only the horizontal velocity too), so the ball leaves at
// v = P cos(elev) / m along d turned by a: speed is the cue ball's speed
// after the strike, P = m speed / cos(elev).  The spin is
// w = r x J / I.  Level (elev = 0) and without squirt this is
// w = (5 v / 2R) (-topback d_y, topback d_x, side): topback = 2/5 rolls at
// once, 0 slides (stun), < 0 draws; side > 0 (tip right of centre, right
// english) gives wz > 0, counter-clockwise seen from above, which throws
// the rebound off a rail to the right.  Raised, the cue gives w a
// horizontal component across the path (from the side offset), so the
// cloth's slip has a sideways part and the sliding ball curves: swerve, and
// at large elevation a masse (motion's sliding state already curves it:
// its friction is constant along the slip u, not along v).
#ifndef C2D_DEMO_MOTION_H
#define C2D_DEMO_MOTION_H

#include <cstdint>

namespace demo {

constexpr double kBallDiameter = 0.05715;
constexpr double kBallRadius = kBallDiameter / 2;
constexpr double kBallMass = 0.17;
constexpr double kBallInertia = 0.4 * kBallMass * kBallRadius * kBallRadius;  // solid sphere, 2/5 m R^2

enum class Motion : uint8_t { Stationary, Spinning, Sliding, Rolling, Pocketed };
const char *motion_name(Motion m);

struct Ball {
    double x, y, vx, vy;
    int number;  // 0 = cue ball, 1..15 object balls; gas: index
    bool active; // on the table
    double wx = 0, wy = 0, wz = 0;  // rad/s
    Motion motion = Motion::Stationary;
};

// The cloth: coefficients of the ball-cloth contact.
struct Cloth {
    double gravity;  // m/s^2
    double slide;    // mu_s, sliding friction
    double roll;     // mu_r, rolling resistance
    double spin;     // mu_sp, spinning friction
    double spin_deceleration() const { return 5 * spin * gravity / (2 * kBallRadius); }  // rad/s^2
};

// One piece of a ball's motion, from t0 until the state changes (t_end).
struct Track {
    Ball start;                  // state at t0
    double t0, t_end;            // s; t_end INFINITY: no change ahead
    double ax, ay;               // linear acceleration over the piece, m/s^2
    double alpha_x, alpha_y;     // angular acceleration about x and y (sliding), rad/s^2
    double spin_rate;            // |dwz/dt| towards 0, rad/s^2
};

// The motion state a ball's velocities put it in (pocketed if inactive).
Motion classify(const Ball &b);
// The piece that starts at t0 with b's state; b.motion must be set
// (classify, or the state a transition leads to).  friction false: the
// frictionless scenes, straight lines for ever.
Track make_track(const Ball &b, double t0, const Cloth &cloth, bool friction);
// Position at t in [t0, t_end].
void position_at(const Track &k, double t, double &x, double &y);
// The whole state at t in [t0, t_end].
Ball state_at(const Track &k, double t);
// The state at the piece's end and what comes next: rolling (w from v
// exactly), spinning, or stationary (v and w exactly 0).
Ball state_after_transition(const Track &k);

// Rolls b: w_xy from v (u = 0 exactly, whatever classify's rounding would
// say), and the motion state that goes with it.
void roll(Ball &b);

// Kinetic energy, rotation included, J.
double energy(const Ball &b);

// The cue's default end mass (kg) that squirt comes from: m / 30, 5.7 g.
// The ratio is pooltool's default (CueSpecs.default(): end_mass =
// 0.170097 / 30 kg, its ball's 6 oz over 30, citing Alciatore's TP A.31);
// with our 0.17 kg ball it is 5.667 g.  Alciatore's endmass FAQ: lighter
// ends (low-deflection shafts) squirt less, added end mass alone more;
// Model::cue_end_mass (--cue-end-mass) sets another.
constexpr double kCueEndMass = kBallMass / 30;

// The squirt angle (rad, > 0 to the left of the aim) of a tip `side` (a
// fraction of R) right of centre, for a cue of end mass end_mass (kg, > 0):
// a heavier end mass squirts more (m / m_e, in the denominator, shrinks),
// which is why low-squirt shafts lighten their last few inches.
double squirt_angle(double side, double end_mass = kCueEndMass);

// The cue ball after a strike along angle_rad at speed v with the tip at
// (side, topback) fractions of R, the cue raised by elevation_rad, the cue's
// end mass end_mass (kg); position and number kept.
Ball strike(const Ball &b, double angle_rad, double speed, double side, double topback, double elevation_rad = 0,
            double end_mass = kCueEndMass);

}  // namespace demo

#endif
