/* SPDX-License-Identifier: MIT */
// test_physics.cpp - the pool model against the textbook laws, through the
// shot seam (simulate_shot / simulate_to_rest: no frames, no SDL), and the
// engine's integrity over random shots (Simulation: frames and the
// independent checker).  Prints each measured law beside its theory.
//   slide     a centre-ball shot slides 12 v^2 / (49 mu_s g), then rolls at
//             5/7 of v and stops after a further (5v/7)^2 / (2 mu_r g)
//   stun      a ball without spin leaves a cut along the tangent line,
//             turned by what restitution and friction leave of the normal
//             and tangential components (derived below)
//   30 deg    a rolling ball's final direction after a cut
//   draw, follow   straight shots come back and go through
//   throw     a rolling cue ball's throw against cut angle: atan(mu(v) sin t)
//             (constant mu and Alciatore's mu(v))
//   roll-out  draw, stun and follow: the cue ball's roll-out velocity and
//             where it starts rolling, in closed form
//   rails     rolling into a rail at 20-70 degrees with reverse, no and
//             running english: Han 2005's rebound and the path once rolling
//   swerve    squirt (TP A.31) and the curve of an elevated cue's shot
//   english   left and right english mirror each other off a rail
// The sphere contact's figures come from the impacts solved by hand with
// 3-vectors below (hit_balls, hit_rail, rolls_at), not from the library.
//   rack      the break's rack: no two balls overlap, each ball within
//             kRackGap of its place in the triangle of pitch 2 (R + kRackGap),
//             the same bits for the same seed, other gaps for another; one
//             solid and one stripe in the back corners; the elastic rack tight
//   break     8 m/s breaks of 50 racks: no group of 7 balls left touching at
//             rest (issue 23's tight rack left 7-15, pooltool none); the
//             collisions, cushion hits and pots printed beside pooltool's
//   random    1,000 random tables (every fourth a full rack) and shots
//             (angles, speeds up to 12 m/s, tips): nothing tunnels or escapes, no
//             overlap deeper than 1e-9 of a diameter, energy (rotation
//             included) never grows from frame to frame, and the framed run
//             ends exactly where the frameless seam does
// usage: test_physics [RANDOM_SHOTS [SEED]]   (default 1000 shots, seed 20261126)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "pool/sim.h"
#include "pool/sphere_contact.h"
#include "tests/check.h"

namespace {

using demo::Ball;
using demo::Event;
using demo::EventKind;
using demo::kBallDiameter;
using demo::kBallRadius;
using demo::Shot;
using demo::ShotOutcome;
using demo::SimConfig;

using demo_tests::check;

Ball ball(int number, double x, double y) { return Ball{x, y, 0, 0, number, true}; }

// The first event of a kind for a ball (by index), after time t.
const Event *first(const ShotOutcome &o, EventKind kind, int ball, double after = -1) {
    for (const Event &e : o.events)
        if (e.kind == kind && e.ball == ball && e.t > after) return &e;
    return nullptr;
}

double degrees(double rad) { return rad * 180.0 / M_PI; }

// --- slide then roll ------------------------------------------------------
void slide_and_roll(const SimConfig &c) {
    const double mu_s = c.model.cloth.slide, mu_r = c.model.cloth.roll, g = c.model.cloth.gravity;
    const double x0 = 0.1, y0 = 0.635;
    for (double v : {0.3, 0.5, 0.7, 2.0}) {
        const ShotOutcome o = demo::simulate_shot(c, {ball(0, x0, y0)}, Shot{0, v});
        const Event *roll = first(o, EventKind::SlideToRoll, 0), *stop = first(o, EventKind::Stop, 0);
        if (!roll || !stop) {
            check(false, "centre ball: slide_to_roll and stop events");
            continue;
        }
        const double slide = 12 * v * v / (49 * mu_s * g), rolled = std::pow(5 * v / 7, 2) / (2 * mu_r * g);
        // the fastest reaches the foot rail: only its slide is checked
        const bool on_table = x0 + slide + rolled < c.table.length - kBallRadius;
        std::printf("    v = %.1f m/s: slid %.9f m (theory %.9f), rolls at %.9f v (5/7 = %.9f)", v, roll->x - x0, slide,
                    roll->vx / v, 5.0 / 7);
        if (on_table) std::printf(", stops after %.9f m (theory %.9f)", stop->x - x0, slide + rolled);
        std::printf("\n");
        const bool ok = std::fabs(roll->x - x0 - slide) < 1e-9 * slide && std::fabs(roll->vx / v - 5.0 / 7) < 1e-12 &&
                        roll->vy == 0 && (!on_table || std::fabs(stop->x - x0 - slide - rolled) < 1e-9 * (slide + rolled));
        check(ok, "centre ball at " + std::to_string(v).substr(0, 3) +
                      " m/s: slides 12 v^2 / (49 mu_s g), then rolls at 5v/7" + (on_table ? " and stops on time" : ""));
    }
    // struck 2/5 R above centre it rolls at once: v^2 / (2 mu_r g) to a stop
    const double v = 0.5;
    const ShotOutcome r = demo::simulate_shot(c, {ball(0, x0, y0)}, Shot{0, v, 0, 0.4});
    const Event *slide_end = first(r, EventKind::SlideToRoll, 0), *stop = first(r, EventKind::Stop, 0);
    const double rolled = v * v / (2 * mu_r * g);
    std::printf("    tip 2/5 R above centre, %.1f m/s: rolls %.9f m (theory %.9f)\n", v, stop ? stop->x - x0 : NAN, rolled);
    check((!slide_end || slide_end->t < 1e-12) && stop && std::fabs(stop->x - x0 - rolled) < 1e-9 * rolled,
          "tip 2/5 R above centre: rolling at once");
}

// The cue ball's velocity right after the impact with an object ball at
// rest, neither spinning (so the sphere contact's slip is horizontal and it
// is the 2-D rough contact of c2d_collide_rough): normal impulse Jn = m (1 + e)
// v cos(t) / 2; the contact points' tangential slip gt = v sin(t) (no z
// spin), stopped by Jt = m gt / 7 (1/m_t = 2/m + 2 R^2 / I = 7/m, beta = 0)
// unless that exceeds mu Jn.  n = line of centres at angle -t from the
// motion (+x), tangent n turned +90 degrees.
void after_impact(double v, double cut, double e, double mu, double &vx, double &vy) {
    const double nx = std::cos(cut), ny = -std::sin(cut), tx = -ny, ty = nx;
    const double jn = (1 + e) / 2 * v * std::cos(cut);  // per unit mass
    const double gt = -v * tx;                            // (vb - va).t, vb = 0
    const double jt = std::fabs(gt) / 7 <= mu * jn ? -gt / 7 : -std::copysign(mu * jn, gt);
    vx = v - (jn * nx + jt * tx);
    vy = -(jn * ny + jt * ty);
}

// Cue ball moving +x at v, touching an object ball at cut angle t (the line
// of centres turned clockwise by t from the motion), with spin w_xy.
ShotOutcome cut_shot(const SimConfig &c, double v, double cut, double wx, double wy) {
    const double x = 1.0, y = 0.5;
    Ball cue = ball(0, x, y);
    cue.vx = v;
    cue.wx = wx;
    cue.wy = wy;
    const Ball object = ball(1, x + kBallDiameter * std::cos(cut), y - kBallDiameter * std::sin(cut));
    return demo::simulate_to_rest(c, {cue, object});
}

// --- stun: along the tangent line -------------------------------------------
void stun(const SimConfig &c) {
    const double v = 2.0, e = c.model.ball.restitution, mu = c.model.ball.friction;
    SimConfig ideal = c;  // the textbook's balls: elastic and smooth
    ideal.model.ball = demo::Surface{1, 0, -1};
    for (double deg : {15.0, 30.0, 45.0, 60.0}) {
        const double cut = deg * M_PI / 180;
        double measured[2];
        for (int real = 0; real < 2; ++real) {
            const ShotOutcome o = cut_shot(real ? c : ideal, v, cut, 0, 0);
            const Event *hit = first(o, EventKind::BallBall, 0);
            const Event *roll = hit ? first(o, EventKind::SlideToRoll, 0, hit->t) : nullptr;
            measured[real] = roll ? degrees(std::atan2(roll->vy, roll->vx)) : NAN;
        }
        double px, py;
        after_impact(v, cut, e, mu, px, py);
        const double predicted = degrees(std::atan2(py, px));
        const double tangent = 90 - deg;  // the tangent line, from the cue ball's path
        std::printf("    cut %2.0f deg: tangent line %4.1f deg; leaves at %.9f deg with e = 1, mu = 0; with e = %.2f, "
                    "mu = %.2f at %8.4f deg (predicted %8.4f)\n",
                    deg, tangent, measured[0], e, mu, measured[1], predicted);
        check(std::fabs(measured[0] - tangent) < 1e-9 && std::fabs(measured[1] - predicted) < 1e-9,
              "stun at cut " + std::to_string(static_cast<int>(deg)) +
                  " deg leaves along the tangent line (exactly for e = 1, mu = 0; as derived for the model's)");
    }
}

// --- the sphere contact, solved by hand -----------------------------------------
// Independent of the library's component formulas: the impact written with
// 3-vectors from its physics (Alciatore TP A.14 for ball-ball, Han 2005 for
// the rail), x, y the cloth, z up, per unit mass (m = 1, I = 2/5 R^2):
//   an impulse P at r from the centre:  v += P,  w += r x P / I;
//   the normal impulse from Newton's restitution on the contact's approach;
//   friction against the tangential slip S of the contact points, of size
//   min(mu Pn, |S| / A), A = the contact's tangential inverse mass (a free
//   sphere's contact point: 1 + R^2 / I = 7/2 per ball, the same in every
//   tangential direction, so S keeps its direction while it slides);
//   then the cloth takes the vertical velocity (a reaction through the
//   centre, no moment).
struct V3 {
    double x, y, z;
};
V3 operator+(const V3 &a, const V3 &b) { return V3{a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(const V3 &a, const V3 &b) { return V3{a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(double k, const V3 &a) { return V3{k * a.x, k * a.y, k * a.z}; }
double dot(const V3 &a, const V3 &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(const V3 &a, const V3 &b) { return V3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double norm(const V3 &a) { return std::sqrt(dot(a, a)); }

struct Moving {
    V3 v, w;
};

constexpr double kInertiaPerMass = 0.4 * kBallRadius * kBallRadius;

// An impulse P (per unit mass) at r from the centre, then the cloth.
void push(Moving &b, const V3 &r, const V3 &p) {
    b.v = b.v + p;
    b.v.z = 0;
    b.w = b.w + (1 / kInertiaPerMass) * cross(r, p);
}

// Ball-ball friction of sliding speed s: mu + boost exp(-decay s).
struct Friction {
    double mu, boost, decay;
    double at(double s) const { return mu + boost * std::exp(-decay * s); }
};

// Ball a hits ball b, the normal n from a to b (horizontal, unit).
void hit_balls(Moving &a, Moving &b, const V3 &n, double e, const Friction &f) {
    const V3 ra = kBallRadius * n, rb = -1.0 * ra;
    const V3 g = (b.v + cross(b.w, rb)) - (a.v + cross(a.w, ra));  // b's contact point past a's
    const double pn = (1 + e) * -dot(g, n) / 2;                     // 1/m_n = 2
    const V3 slip = g - dot(g, n) * n;
    const double s = norm(slip), lambda = s > 0 ? std::fmin(f.at(s) * pn, s / 7) : 0;  // A = 2 (7/2)
    const V3 on_b = pn * n - (s > 0 ? lambda / s : 0) * slip;
    push(b, rb, on_b);
    push(a, ra, -1.0 * on_b);
}

// A ball hits a rail whose nose is h above the cloth; n horizontal, from
// the ball to the rail (Han 2005: the contact at R nu, nu = cos th n +
// sin th z, sin th = h / R - 1).
void hit_rail(Moving &b, const V3 &n, double h, double e, double mu) {
    const double sn = h / kBallRadius - 1, cs = std::sqrt(1 - sn * sn);
    const V3 nu = cs * n + sn * V3{0, 0, 1}, r = kBallRadius * nu;
    const double pn = (1 + e) * dot(b.v, nu);  // inverse mass 1 along nu (r x nu = 0)
    const V3 c = b.v + cross(b.w, r);
    const V3 slip = c - dot(c, nu) * nu;
    const double s = norm(slip), lambda = s > 0 ? std::fmin(mu * pn, s / 3.5) : 0;  // A = 7/2
    push(b, r, -pn * nu - (s > 0 ? lambda / s : 0) * slip);
}

// The velocity a sliding ball rolls at: its cloth slip u = v + w x (-R z)
// keeps its direction while friction acts (motion.h), and v changes by
// -(2/7) u0 by then (du/dt = (7/2) dv/dt).
V3 rolls_at(const Moving &b) {
    const V3 u = b.v + cross(b.w, V3{0, 0, -kBallRadius});
    return b.v - (2.0 / 7) * V3{u.x, u.y, 0};
}

// --- the 30-degree rule -------------------------------------------------------
// A rolling cue ball (w_xy = (0, v/R)) cut at t: hit_balls, then it slides
// until it rolls again (rolls_at).  With mu = 0 the top spin stays and
// v_f = v sin(t) t^ + k v cos(t) n^, k = (5 (1 - e)/2 + 2) / 7 =
// (9 - 5e)/14, so tan(deflection) = (1 - k) sin t cos t / (sin^2 t + k cos^2 t),
// which for e = 1 (k = 2/7) is the textbook sin t cos t / (sin^2 t + 2/5).
// With friction the vertical slip from the top spin takes some of it away
// at the impact (the sphere model), and the cue ball turns further.
double deflection(double cut, double e, double mu) {
    Moving a{{1, 0, 0}, {0, 1 / kBallRadius, 0}}, b{{0, 0, 0}, {0, 0, 0}};
    hit_balls(a, b, V3{std::cos(cut), -std::sin(cut), 0}, e, Friction{mu, 0, 0});
    const V3 f = rolls_at(a);
    return degrees(std::atan2(f.y, f.x));
}

void thirty_degree_rule(const SimConfig &c) {
    const double v = 2.0, e = c.model.ball.restitution, mu = c.model.ball.friction;
    for (double deg : {10.0, 20.0, 30.0, 40.0, 50.0, 60.0}) {
        const double cut = deg * M_PI / 180;
        const double textbook = degrees(std::atan(std::sin(cut) * std::cos(cut) / (std::pow(std::sin(cut), 2) + 0.4)));
        const double k = (9 - 5 * e) / 14;
        const double with_e = degrees(std::atan((1 - k) * std::sin(cut) * std::cos(cut) /
                                                (std::pow(std::sin(cut), 2) + k * std::pow(std::cos(cut), 2))));
        SimConfig smooth = c;
        smooth.model.ball.friction = 0;
        double measured[2];
        for (int f = 0; f < 2; ++f) {
            const ShotOutcome o = cut_shot(f ? c : smooth, v, cut, 0, v / kBallRadius);
            const Event *hit = first(o, EventKind::BallBall, 0);
            const Event *roll = hit ? first(o, EventKind::SlideToRoll, 0, hit->t) : nullptr;
            measured[f] = roll ? degrees(std::atan2(roll->vy, roll->vx)) : NAN;
        }
        std::printf("    cut %2.0f deg: deflection %7.4f deg without ball friction (theory with e: %7.4f; textbook "
                    "e = 1: %7.4f), %7.4f with mu = %.2f (theory %7.4f)\n",
                    deg, measured[0], with_e, textbook, measured[1], mu, deflection(cut, e, mu));
        check(std::fabs(measured[0] - with_e) < 1e-9 && std::fabs(with_e - deflection(cut, e, 0)) < 1e-9 &&
                  std::fabs(measured[1] - deflection(cut, e, mu)) < 1e-9,
              "30-degree rule at cut " + std::to_string(static_cast<int>(deg)) + " deg, corrected for e (and mu)");
    }
}

// --- draw and follow ----------------------------------------------------------
void draw_and_follow(const SimConfig &c) {
    const double y = 0.635, cue_x = 0.8, object_x = 1.3;
    for (double topback : {-0.4, 0.4}) {
        const ShotOutcome o = demo::simulate_shot(c, {ball(0, cue_x, y), ball(1, object_x, y)}, Shot{0, 2, 0, topback});
        const Event *hit = first(o, EventKind::BallBall, 0);
        const double final_x = o.balls[0].x;
        std::printf("    topback %+.1f: impact at x = %.4f, the cue ball ends at x = %.4f (y = %.6f)\n", topback,
                    hit ? hit->x : NAN, final_x, o.balls[0].y);
        if (topback < 0)
            check(hit && final_x < hit->x - 0.1 && o.balls[0].y == y, "draw: the cue ball comes back along its line");
        else
            check(hit && final_x > object_x + 0.1 && o.balls[0].y == y, "follow: the cue ball goes through");
    }
}

// --- throw: a rolling cue ball against cut angle ------------------------------
// The object ball leaves the line of centres by the throw angle.  For a
// rolling cue ball (no wz) the slip of the contact points has a horizontal
// part v sin(t) (the cue ball's tangential velocity) and a vertical part
// v cos(t) (its topspin, R w = v): |S| = v whatever the cut.  The ball
// slides all through the impact when mu Pn < |S| / 7, Pn = (1 + e) v cos(t) / 2,
// i.e. cos(t) < 2 / (7 mu (1 + e)) (always, for mu < 0.14): the friction
// mu Pn along S^ has the horizontal part mu Pn sin(t), so
//     tan(throw) = mu(v) sin(t),
// mu(v) the friction at sliding speed v (Alciatore TP A.14's throw with
// the vertical slip; constant mu, or a + b exp(-c v)).  A stun ball (|S| =
// v sin t, no vertical part) throws by atan(mu) instead, a rolling one far
// less at small cuts.  Checked: the engine's object ball after the impact
// against hit_balls, and hit_balls against the closed form.
void throw_angles(const SimConfig &c, const char *name, const Friction &f) {
    const double v = 2.0, e = c.model.ball.restitution;
    int ran = 0;
    for (double deg : {10.0, 15.0, 20.0, 30.0, 40.0, 45.0, 50.0, 60.0, 70.0}) {
        const double cut = deg * M_PI / 180;
        const ShotOutcome o = cut_shot(c, v, cut, 0, v / kBallRadius);
        const Event *hit = first(o, EventKind::BallBall, 1);
        const Event *roll = hit ? first(o, EventKind::SlideToRoll, 1, hit->t) : nullptr;
        Moving a{{v, 0, 0}, {0, v / kBallRadius, 0}}, b{{0, 0, 0}, {0, 0, 0}};
        hit_balls(a, b, V3{std::cos(cut), -std::sin(cut), 0}, e, f);
        const V3 later = rolls_at(b);
        const double measured = hit ? degrees(std::atan2(hit->vy, hit->vx)) + deg : NAN;
        const double by_hand = degrees(std::atan2(b.v.y, b.v.x)) + deg;
        const double closed = degrees(std::atan(f.at(v) * std::sin(cut)));
        const double rolled = roll ? degrees(std::atan2(roll->vy, roll->vx)) + deg : NAN;
        std::printf("    %s, cut %2.0f deg: throw %.4f deg (hand %.4f, closed form %.4f); once the object ball "
                    "rolls %.4f (hand %.4f)\n",
                    name, deg, measured, by_hand, closed, rolled, degrees(std::atan2(later.y, later.x)) + deg);
        check(std::fabs(measured - by_hand) < 1e-9 && std::fabs(by_hand - closed) < 1e-9 &&
                  std::fabs(rolled - (degrees(std::atan2(later.y, later.x)) + deg)) < 1e-9,
              std::string("rolling-ball throw, ") + name + ", cut " + std::to_string(static_cast<int>(deg)) +
                  " deg: atan(mu(v) sin t)");
        ++ran;
    }
    check(ran == 9, "throw: all 9 cuts ran");
}

// --- draw, stun and follow: the cue ball's roll-out -------------------------------
// A straight shot (tip topback T of R, level, speed v0) at an object ball
// at rest a distance L (centres' gap less D) ahead.  By hand:
//   strike   R wy0 = (5/2) v0 T (motion.h); the cloth slip u0 = v0 - R wy0
//   cloth    sliding, a = -mu_s g sign(u0), R wy changes by -(5/2) a t, until
//            t_r = 2 |u0| / (7 mu_s g); then rolling at v0 - (2/7) u0 with
//            -mu_r g.  Impact at the first time the path reaches L.
//   impact   head on, n = x: the cue's contact slip is vertical, R wy_i;
//            Pn = (1 + e) v_i / 2, friction lambda = min(mu Pn, |R wy_i| / 7)
//            takes back spin or top spin away: R wy' = R wy_i - (5/2) lambda
//            sign(wy_i); the cue keeps v' = (1 - e) v_i / 2.
//   roll-out v_f = (5/7) v' + (2/7) R wy'  (rolls_at), reached after sliding
//            x' = v' t' + a' t'^2 / 2, t' = 2 |v' - R wy'| / (7 mu_s g).
// The disk model never changes wy at the impact (lambda = 0 for the vertical
// slip): its draw comes back 5/2 lambda (2/7) faster.
void roll_out(const SimConfig &c) {
    const double v0 = 2.0, y = 0.635, cue_x = 0.8, object_x = 1.3, L = object_x - cue_x - kBallDiameter;
    const double e = c.model.ball.restitution, mu = c.model.ball.friction;
    const double mu_s = c.model.cloth.slide, mu_r = c.model.cloth.roll, g = c.model.cloth.gravity;
    int ran = 0;
    for (double topback : {-0.5, -0.25, 0.0, 0.25, 0.5}) {
        const ShotOutcome o = demo::simulate_shot(c, {ball(0, cue_x, y), ball(1, object_x, y)}, Shot{0, v0, 0, topback});
        const Event *hit = first(o, EventKind::BallBall, 0);
        const Event *roll = hit ? first(o, EventKind::SlideToRoll, 0, hit->t) : nullptr;
        // the approach
        const double u0 = v0 - 2.5 * v0 * topback, a = -mu_s * g * (u0 > 0 ? 1 : -1);
        const double t_r = 2 * std::fabs(u0) / (7 * mu_s * g), x_r = v0 * t_r + 0.5 * a * t_r * t_r;
        double vi, rwi;
        if (x_r >= L) {
            const double t = (-v0 + std::sqrt(v0 * v0 + 2 * a * L)) / a;
            vi = v0 + a * t;
            rwi = 2.5 * v0 * topback - 2.5 * a * t;
        } else {
            const double vr = v0 - 2.0 / 7 * u0;
            vi = rwi = std::sqrt(vr * vr - 2 * mu_r * g * (L - x_r));
        }
        // the impact and the slide after it
        const double pn = (1 + e) * vi / 2, lambda = std::fmin(mu * pn, std::fabs(rwi) / 7);
        const double v1 = (1 - e) * vi / 2, rw1 = rwi - 2.5 * lambda * (rwi > 0 ? 1 : -1);
        const double vf = 5.0 / 7 * v1 + 2.0 / 7 * rw1, u1 = v1 - rw1;
        const double t1 = 2 * std::fabs(u1) / (7 * mu_s * g), a1 = -mu_s * g * (u1 > 0 ? 1 : -1);
        const double x1 = v1 * t1 + 0.5 * a1 * t1 * t1, run = std::copysign(vf * vf / (2 * mu_r * g), vf);
        std::printf("    tip %+.2f R at %.0f m/s: impact at %.6f m/s, R wy %+.6f; rolls out at %+.6f m/s (hand %+.6f) "
                    "%+.6f m past the impact (hand %+.6f); then %+.4f m rolling: draw/follow %+.4f m\n",
                    topback, v0, vi, rwi, roll ? roll->vx : NAN, vf, roll && hit ? roll->x - hit->x : NAN, x1, run,
                    x1 + run);
        check(hit && roll && std::fabs(roll->vx - vf) < 1e-9 && std::fabs(roll->x - hit->x - x1) < 1e-9 &&
                  roll->vy == 0,
              "tip " + std::to_string(topback).substr(0, 5) +
                  " R straight shot: the cue ball's roll-out velocity and where it starts rolling, by hand");
        ++ran;
    }
    check(ran == 5, "roll-out: all 5 tips ran");
}

// --- rail rebound: rolling into a cushion, with english ---------------------------
// A ball rolling at v into the foot rail (normal +x) at angle th from the
// normal, with wz (running english: the spin a ball rolling along the rail
// would have, wz < 0 here; reverse: wz > 0), starting 1 cm from it.  By
// hand: the rolling approach (decelerating at mu_r g, wz decaying at the
// spinning rate), hit_rail (Han 2005 at the model's nose height), and the
// angle from the normal once the ball rolls again (rolls_at).
void rails(const SimConfig &c) {
    const double v = 1.5, gap = 0.01, h = c.model.cushion_height, e = c.model.cushion.restitution;
    const double mu = c.model.cushion.friction, g = c.model.cloth.gravity, rate = c.model.cloth.spin_deceleration();
    const double wz_english = 2.5 * v / kBallRadius * 0.3;  // a tip 0.3 R off centre at this speed
    int ran = 0;
    for (double deg : {20.0, 30.0, 40.0, 50.0, 60.0, 70.0}) {
        for (int way = -1; way <= 1; ++way) {  // english: reverse, none, running
            const double th = deg * M_PI / 180, wz0 = -way * wz_english;
            const double dx = std::cos(th), dy = std::sin(th);
            Ball b = ball(0, c.table.length - kBallRadius - gap, 0.3);
            b.vx = v * dx, b.vy = v * dy, b.wx = -b.vy / kBallRadius, b.wy = b.vx / kBallRadius, b.wz = wz0;
            const ShotOutcome o = demo::simulate_to_rest(c, {b});
            const Event *hit = first(o, EventKind::Cushion, 0);
            const Event *roll = hit ? first(o, EventKind::SlideToRoll, 0, hit->t) : nullptr;
            const double path = gap / dx, dec = c.model.cloth.roll * g;
            const double t = (v - std::sqrt(v * v - 2 * dec * path)) / dec, vi = v - dec * t;
            const double wzi = std::copysign(std::fmax(0.0, std::fabs(wz0) - rate * t), wz0);
            Moving m{{vi * dx, vi * dy, 0}, {-vi * dy / kBallRadius, vi * dx / kBallRadius, wzi}};
            hit_rail(m, V3{1, 0, 0}, h, e, mu);
            const V3 f = rolls_at(m);
            const double measured = roll ? degrees(std::atan2(roll->vy, -roll->vx)) : NAN;
            const double by_hand = degrees(std::atan2(f.y, -f.x));
            const char *kind = way < 0 ? "reverse" : way > 0 ? "running" : "none";
            std::printf("    %2.0f deg, english %-7s: rebounds at (%+.6f, %+.6f) m/s (hand (%+.6f, %+.6f)); rolling "
                        "again at %.4f deg from the normal (hand %.4f), %.4f m/s\n",
                        deg, kind, hit ? hit->vx : NAN, hit ? hit->vy : NAN, m.v.x, m.v.y, measured, by_hand,
                        roll ? std::hypot(roll->vx, roll->vy) : NAN);
            check(hit && roll && std::fabs(hit->vx - m.v.x) < 1e-9 && std::fabs(hit->vy - m.v.y) < 1e-9 &&
                      std::fabs(measured - by_hand) < 1e-9,
                  "rolling into the rail at " + std::to_string(static_cast<int>(deg)) + " deg, english " + kind +
                      ": Han 2005's rebound and the path once rolling, by hand");
            ++ran;
        }
    }
    check(ran == 18, "rails: all 18 shots ran");
}

// --- squirt, swerve and masse ---------------------------------------------------
// The strike by hand, with 3-vectors: the cue along D = cos(elev) x -
// sin(elev) z (aimed at +x), the tip at r = R (side e_right + topback e_up -
// sqrt(1 - side^2 - topback^2) D), e_right = -y, e_up = sin(elev) x +
// cos(elev) z; the impulse along D turned left about z by the squirt angle
// atan((5/2) s sqrt(1 - s^2) / (1 + m/m_e + (5/2)(1 - s^2))) (Alciatore TP
// A.31, m_e = m/30), its size m speed / cos(elev) (the cloth takes the
// vertical part); w = r x J / I.  Level, the ball leaves squirted and goes
// straight on (w's horizontal part along v); raised, the side offset puts a
// spin across the path, the cloth's slip gets a sideways part and the ball
// curves towards the side of the tip (swerve; at 60 degrees and more a
// masse) until it rolls along rolls_at.
void swerve(const SimConfig &c) {
    const double v = 1.0, me = demo::kBallMass / 30;
    int ran = 0;
    for (double elev : {0.0, 15.0, 30.0, 60.0}) {
        for (double side : {-0.3, 0.3}) {
            const double th = elev * M_PI / 180, topback = -0.1, cc = std::sqrt(1 - side * side - topback * topback);
            const V3 d{std::cos(th), 0, -std::sin(th)}, right{0, -1, 0}, up{std::sin(th), 0, std::cos(th)};
            const V3 r = kBallRadius * (side * right + topback * up - cc * d);
            const double a = std::atan(2.5 * side * std::sqrt(1 - side * side) /
                                       (1 + demo::kBallMass / me + 2.5 * (1 - side * side)));
            const V3 j = (v / std::cos(th)) * V3{std::cos(th) * std::cos(a), std::cos(th) * std::sin(a), -std::sin(th)};
            Moving m{{j.x, j.y, 0}, (1 / kInertiaPerMass) * cross(r, j)};
            const V3 f = rolls_at(m);
            const ShotOutcome o = demo::simulate_shot(c, {ball(0, 0.5, 0.635)}, Shot{0, v, side, topback, elev});
            const Event *strike = first(o, EventKind::Strike, 0), *roll = first(o, EventKind::SlideToRoll, 0);
            const double leaves = strike ? degrees(std::atan2(strike->vy, strike->vx)) : NAN;
            const double rolls = roll ? degrees(std::atan2(roll->vy, roll->vx)) : NAN;
            const double hand = degrees(std::atan2(f.y, f.x));
            std::printf("    cue %2.0f deg up, tip %+.1f R side: leaves at %+.4f deg (squirt %+.4f), rolls on at %+.4f "
                        "deg (hand %+.4f)\n",
                        elev, side, leaves, degrees(a), rolls, hand);
            // curving towards the tip's side: right (-y, a smaller angle) for side > 0
            const bool curves = elev == 0 ? std::fabs(rolls - leaves) < 1e-9 : (rolls - leaves) * side < 0;
            check(std::fabs(leaves - degrees(a)) < 1e-9 && std::fabs(rolls - hand) < 1e-9 && curves,
                  "cue " + std::to_string(static_cast<int>(elev)) + " deg up, side " + std::to_string(side).substr(0, 4) +
                      ": squirt (TP A.31), then " + (elev == 0 ? "straight" : "curving to the tip's side"));
            ++ran;
        }
    }
    check(ran == 8, "swerve: all 8 strikes ran");
}

// --- squirt against the cue's end mass --------------------------------------------
// Model::cue_end_mass (--cue-end-mass): the level strike's direction against
// Alciatore's closed form (TP A.31), tan a = (5/2) s sqrt(1 - s^2) / (1 + m/m_e
// + (5/2)(1 - s^2)), at the default m/30 (pooltool's CueSpecs default) and at
// 12 g, for tips 0.1-0.5 R to either side; a heavier end mass squirts more,
// and the default is m/30 exactly.
void squirt_end_mass(const SimConfig &c) {
    check(c.model.cue_end_mass == demo::kBallMass / 30, "cue end mass: the default is m/30 (pooltool's)");
    int ran = 0;
    for (double grams : {demo::kBallMass * 1000 / 30, 12.0}) {
        SimConfig cue = c;
        cue.model.cue_end_mass = grams / 1000;
        for (double side : {-0.5, -0.3, -0.1, 0.1, 0.3, 0.5}) {
            const double ratio = 0.17 / (grams / 1000), across = 1 - side * side;
            const double closed = degrees(std::atan(2.5 * side * std::sqrt(across) / (1 + ratio + 2.5 * across)));
            const ShotOutcome o = demo::simulate_shot(cue, {ball(0, 0.5, 0.635)}, Shot{0, 1, side, 0});
            const Event *strike = first(o, EventKind::Strike, 0);
            const double leaves = strike ? degrees(std::atan2(strike->vy, strike->vx)) : NAN;
            if (side == 0.3)
                std::printf("    end mass %6.3f g, tip %+.1f R: leaves at %+.6f deg (TP A.31 %+.6f)\n", grams, side,
                            leaves, closed);
            char name[64];
            std::snprintf(name, sizeof name, "cue end mass %.3f g, side %+.1f R: squirt as TP A.31", grams, side);
            check(std::fabs(leaves - closed) < 1e-9, name);
            ++ran;
        }
    }
    const double light = demo::squirt_angle(0.3, 0.004), heavy = demo::squirt_angle(0.3, 0.015);
    check(ran == 12 && 0 < light && light < demo::squirt_angle(0.3) && demo::squirt_angle(0.3) < heavy,
          "cue end mass: all 12 strikes ran; a heavier end mass squirts more (4 g < m/30 < 15 g)");
}

// --- english off a rail ---------------------------------------------------------
void english(const SimConfig &c) {
    const double y = 0.635, x = 1.9;
    double end_y[2], end_x[2];
    for (int k = 0; k < 2; ++k) {
        const ShotOutcome o = demo::simulate_shot(c, {ball(0, x, y)}, Shot{0, 1.5, k ? 0.3 : -0.3, 0});
        end_x[k] = o.balls[0].x;
        end_y[k] = o.balls[0].y;
    }
    std::printf("    head-on into the foot rail: left english ends at (%.6f, %+.6f), right at (%.6f, %+.6f) from "
                "the line\n",
                end_x[0], end_y[0] - y, end_x[1], end_y[1] - y);
    // shooting towards +x, the shooter's right is -y
    check(std::fabs((end_y[0] - y) + (end_y[1] - y)) < 1e-9 && std::fabs(end_x[0] - end_x[1]) < 1e-9 &&
              end_y[1] - y < -0.02,
          "left and right english mirror each other off a rail (right english: rebound to the right)");
}

// --- random shots: integrity ------------------------------------------------------
struct Worst {
    long tunnelled = 0, escaped = 0, capped = 0, mismatched = 0, unsettled = 0, reported = 0;
    long tree_compared = 0, tree_mismatched = 0;
    double overlap = 0, energy_gain = 0;
    long events = 0, frames = 0;
};

// Two records of one event, bit for bit.
bool same_record(const demo::Event &a, const demo::Event &b) {
    return a.t == b.t && a.kind == b.kind && a.ball == b.ball && a.other == b.other && a.feature == b.feature &&
           a.x == b.x && a.y == b.y && a.vx == b.vx && a.vy == b.vy && a.wx == b.wx && a.wy == b.wy && a.wz == b.wz &&
           a.impulse == b.impulse;
}

// The same shot with the world's own cells finding the candidates instead
// of Box2D's tree: the world promises the same bits whatever broadphase.
bool same_with_cells(const SimConfig &c, const std::vector<Ball> &start, const Shot &shot, const ShotOutcome &tree) {
    SimConfig cells = c;
    cells.broadphase = demo::WorldBroadphase::Cells;
    const ShotOutcome o = demo::simulate_shot(cells, start, shot);
    if (o.events.size() != tree.events.size()) return false;
    for (size_t k = 0; k < o.events.size(); ++k)
        if (!same_record(o.events[k], tree.events[k])) return false;
    for (size_t i = 0; i < start.size(); ++i)
        if (o.balls[i].x != tree.balls[i].x || o.balls[i].y != tree.balls[i].y) return false;
    return true;
}

void random_shots(int count, uint64_t seed) {
    demo::Rng rng(seed);
    Worst w;
    for (int s = 0; s < count; ++s) {
        SimConfig c;
        const int n = 1 + static_cast<int>(rng.next() % 16);
        const demo::Table table = demo::scene_table(c.scene, c.table);
        if (s % 4 == 3) {  // a break: the rack, the cue ball anywhere behind the head string
            const demo::Setup racked = demo::set_up(c.scene, c.table, 0, rng.next());
            c.placements.push_back({0, kBallRadius + rng.uniform() * (0.25 * table.length - kBallRadius),
                                    kBallRadius + rng.uniform() * (table.width - kBallDiameter)});
            for (size_t i = 1; i < racked.balls.size(); ++i)
                c.placements.push_back({racked.balls[i].number, racked.balls[i].x, racked.balls[i].y});
        }
        while (static_cast<int>(c.placements.size()) < n) {
            const double x = kBallRadius + rng.uniform() * (table.length - kBallDiameter);
            const double y = kBallRadius + rng.uniform() * (table.width - kBallDiameter);
            std::vector<demo::Placement> p = c.placements;
            p.push_back({static_cast<int>(p.size()), x, y});
            if (demo::placement_error(table, p).empty()) c.placements = p;
        }
        // half the shots aim at a ball (within a ball's width), half anywhere
        const demo::Placement &cue = c.placements[0], &target = c.placements[rng.next() % c.placements.size()];
        double angle = 360 * rng.uniform();
        if (rng.next() % 2 && &target != &cue) {
            const double d = std::hypot(target.x - cue.x, target.y - cue.y);
            angle = degrees(std::atan2(target.y - cue.y, target.x - cue.x) + std::asin(std::min(1.0, kBallDiameter / d)) *
                                                                                 (2 * rng.uniform() - 1));
        }
        const double r = 0.5 * std::sqrt(rng.uniform()), a = 2 * M_PI * rng.uniform();
        const Shot shot{angle, 0.05 + 11.95 * rng.uniform(), r * std::cos(a), r * std::sin(a)};
        demo::Simulation sim(c);
        sim.shoot(shot);
        double e = sim.energy();
        while (!sim.at_rest() && sim.stats().steps < 60L * 3600) {
            sim.step();
            const double e1 = sim.energy();
            w.energy_gain = std::max(w.energy_gain, (e1 - e) / std::max(e, 1e-300));
            e = e1;
            w.events += static_cast<long>(sim.frame_events().size());
        }
        const demo::Stats &st = sim.stats();
        if ((st.event_cap_frames || st.tunnelled || st.max_overlap >= 1e-9 || st.escaped) && ++w.reported <= 3) {
            std::printf("    shot %d fails; to see it: billiards --headless", s);  // the same run from the command line
            for (const demo::Placement &p : c.placements) std::printf(" --place %d,%.17g,%.17g", p.number, p.x, p.y);
            std::printf(" --shot %.17g,%.17g,%.17g,%.17g\n", shot.angle_deg, shot.speed, shot.side, shot.topback);
        }
        w.frames += st.steps;
        w.tunnelled += st.tunnelled;
        w.escaped += st.escaped;
        w.capped += st.event_cap_frames;
        w.overlap = std::max(w.overlap, st.max_overlap);
        w.unsettled += !sim.at_rest();
        // the seam, without frames, ends in exactly the same state
        std::vector<Ball> start;
        for (const demo::Placement &p : c.placements) start.push_back(ball(p.number, p.x, p.y));
        const ShotOutcome o = demo::simulate_shot(c, start, shot);
        for (size_t i = 0; i < start.size(); ++i) {
            const Ball &seam = o.balls[i], &framed = sim.balls()[i];
            if (seam.x != framed.x || seam.y != framed.y || seam.active != framed.active) ++w.mismatched;
        }
        if (s % 10 == 0) {  // every tenth shot again on the world's cells
            ++w.tree_compared;
            w.tree_mismatched += !same_with_cells(c, start, shot, o);
        }
    }
    std::printf("    %d random shots: %ld frames, %ld events; tunnelled %ld, escaped %ld, worst overlap %.3g of a "
                "diameter, event budget exhausted in %ld frames, largest energy rise between frames %.3g (relative), "
                "not at rest %ld, seam/frames mismatches %ld\n",
                count, w.frames, w.events, w.tunnelled, w.escaped, w.overlap, w.capped, w.energy_gain, w.unsettled,
                w.mismatched);
    check(w.tunnelled == 0 && w.escaped == 0 && w.overlap < 1e-9 && w.capped == 0 && w.unsettled == 0,
          "random shots: 0 tunnelled, 0 escaped, overlap < 1e-9 D, all at rest");
    check(w.energy_gain <= 1e-12, "random shots: energy (rotation included) never grows (rounding aside, 1e-12)");
    check(w.mismatched == 0, "random shots: the frameless seam ends where the framed run does, bit for bit");
    std::printf("    %ld shots again with the world's cells instead of Box2D's tree: %ld differ\n", w.tree_compared,
                w.tree_mismatched);
    check(w.tree_compared == (count + 9) / 10 && w.tree_mismatched == 0,
          "random shots: Box2D's tree and the world's cells give the same events and ends, bit for bit");
}

// --- the rack and the break ---------------------------------------------

// Ball k of the rack (1..15, in the order set_up makes them: rows from the
// apex, each from -y to +y) at its place in the triangle of pitch p.
void rack_place(const demo::Table &t, int k, double pitch, double &x, double &y) {
    int row = 0, row_start = 1;
    while (k >= row_start + row + 1) row_start += ++row;
    x = 0.75 * t.length + row * 0.5 * pitch * std::sqrt(3.0);
    y = 0.5 * t.width + ((k - row_start) - 0.5 * row) * pitch;
}

bool solid(int n) { return n >= 1 && n <= 7; }

void rack() {
    const double gap = demo::kRackGap, pitch = kBallDiameter + 2 * gap;
    bool apart = true, placed = true, corners = true, spots = true, same = true, differ = true;
    double least = INFINITY, most = 0, sum = 0;
    long pairs = 0;
    for (uint64_t seed = 1; seed <= 200; ++seed) {
        const demo::Setup s = demo::set_up(demo::Scene::Break, demo::TableSpec{}, 0, seed);
        const demo::Setup again = demo::set_up(demo::Scene::Break, demo::TableSpec{}, 0, seed);
        const demo::Setup other = demo::set_up(demo::Scene::Break, demo::TableSpec{}, 0, seed + 1000);
        for (size_t i = 0; i < s.balls.size(); ++i) {
            same = same && s.balls[i].x == again.balls[i].x && s.balls[i].y == again.balls[i].y &&
                   s.balls[i].number == again.balls[i].number;
            if (i > 0) differ = differ && (s.balls[i].x != other.balls[i].x || s.balls[i].y != other.balls[i].y);
        }
        for (int k = 1; k <= 15; ++k) {
            double x, y;
            rack_place(s.table, k, pitch, x, y);
            const Ball &b = s.balls[static_cast<size_t>(k)];
            placed = placed && std::hypot(b.x - x, b.y - y) <= gap * (1 + 1e-9);
            for (int m = k + 1; m <= 15; ++m) {
                const Ball &o = s.balls[static_cast<size_t>(m)];
                const double d = std::hypot(b.x - o.x, b.y - o.y) - kBallDiameter;
                apart = apart && d >= 0;
                if (d < kBallDiameter / 2) {  // neighbours in the triangle
                    least = std::min(least, d), most = std::max(most, d), sum += d, ++pairs;
                }
            }
        }
        spots = spots && s.balls[1].number == 1 && s.balls[5].number == 8;
        corners = corners && solid(s.balls[11].number) != solid(s.balls[15].number);
    }
    std::printf("    200 racks: neighbours %.1f to %.1f um apart (theory 0 to %.1f), mean %.1f um (theory %.1f)\n",
                least * 1e6, most * 1e6, 4 * gap * 1e6, sum / static_cast<double>(pairs) * 1e6, 2 * gap * 1e6);
    check(apart && placed, "rack: no two balls overlap, each within kRackGap of its place (200 seeds)");
    check(most <= 4 * gap * (1 + 1e-9) && most > 3 * gap && least < gap,
          "rack: the neighbours' gaps fill 0 to 4 kRackGap (200 seeds)");
    check(same && differ, "rack: the same seed gives the same bits, another seed other gaps");
    check(spots && corners, "rack: the 1 at the apex, the 8 in the middle, one solid and one stripe in the back corners");
    const demo::Setup e = demo::set_up(demo::Scene::Elastic, demo::TableSpec{}, 0, 1);
    bool tight = true;
    for (int k = 1; k <= 15; ++k) {
        double x, y;
        rack_place(e.table, k, kBallDiameter, x, y);
        tight = tight && std::fabs(e.balls[static_cast<size_t>(k)].x - x) < 1e-12 &&
                std::fabs(e.balls[static_cast<size_t>(k)].y - y) < 1e-12;
    }
    check(tight, "rack: the elastic scene's rack stays tight");
}

// The largest group of balls on the table touching each other (centres
// less than a diameter + tol apart), directly or through others.
size_t largest_touching(const std::vector<Ball> &balls, double tol) {
    std::vector<int> group(balls.size(), -1);
    size_t largest = 0;
    for (size_t i = 0; i < balls.size(); ++i) {
        if (!balls[i].active || group[i] >= 0) continue;
        std::vector<size_t> todo = {i};
        group[i] = static_cast<int>(i);
        size_t size = 0;
        while (!todo.empty()) {
            const size_t k = todo.back();
            todo.pop_back();
            ++size;
            for (size_t m = 0; m < balls.size(); ++m)
                if (balls[m].active && group[m] < 0 &&
                    std::hypot(balls[m].x - balls[k].x, balls[m].y - balls[k].y) < kBallDiameter + tol) {
                    group[m] = static_cast<int>(i);
                    todo.push_back(m);
                }
        }
        largest = std::max(largest, size);
    }
    return largest;
}

void break_scatters(const SimConfig &c) {
    const int racks = 50;
    long collisions = 0, cushions = 0, pots = 0;
    size_t cluster = 0;
    bool settled = true;
    for (uint64_t seed = 1; seed <= racks; ++seed) {
        const demo::Setup s = demo::set_up(demo::Scene::Break, c.table, 0, seed);
        const ShotOutcome o = demo::simulate_shot(c, s.balls, Shot{0, 8});
        settled = settled && o.settled;
        collisions += o.stats.ball_ball_collisions, cushions += o.stats.cushion_collisions, pots += o.stats.pocketed;
        cluster = std::max(cluster, largest_touching(o.balls, 1e-6));
    }
    std::printf("    8 m/s, %d racks: %.1f ball-ball collisions, %.1f cushion hits, %.2f balls pocketed a break, "
                "largest group left touching %zu (issue 23, 9 breaks: pooltool 109, 19, 0.67, none; the tight rack then 28, 8, 0, 7-15)\n",
                racks, collisions / double(racks), cushions / double(racks), pots / double(racks), cluster);
    check(settled && cluster < 7, "break at 8 m/s, 50 racks: no group of 7 balls left touching at rest (the tight rack's least)");
}

}  // namespace

int main(int argc, char **argv) {
    const int shots = argc > 1 ? static_cast<int>(std::strtol(argv[1], nullptr, 10)) : 1000;
    const uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 20261126;
    SimConfig c;  // the pool model, break table
    std::printf("# slide, roll, stop\n");
    slide_and_roll(c);
    std::printf("# stun shots\n");
    stun(c);
    std::printf("# rolling cue ball after a cut (30-degree rule)\n");
    thirty_degree_rule(c);
    std::printf("# draw and follow\n");
    draw_and_follow(c);
    std::printf("# throw of a rolling cue ball\n");
    throw_angles(c, "constant mu", Friction{c.model.ball.friction, 0, 0});
    SimConfig alciatore = c;
    alciatore.model.contact = demo::ContactModel::SphereAlciatore;
    throw_angles(alciatore, "Alciatore mu(v)",
                 Friction{demo::kAlciatoreA, demo::kAlciatoreB, demo::kAlciatoreC});
    std::printf("# draw, stun and follow: the roll-out\n");
    roll_out(c);
    std::printf("# rolling into a rail, with and without english\n");
    rails(c);
    std::printf("# squirt, swerve and masse\n");
    swerve(c);
    std::printf("# squirt against the cue's end mass\n");
    squirt_end_mass(c);
    std::printf("# english off a rail\n");
    english(c);
    std::printf("# the rack and the break\n");
    rack();
    break_scatters(c);
    std::printf("# integrity\n");
    random_shots(shots, seed);
    return demo_tests::check_summary("test_physics");
}
