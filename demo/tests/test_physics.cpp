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
//   english   left and right english mirror each other off a rail
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
// rest (2-D rough contact, c2d_collide_rough): normal impulse Jn = m (1 + e)
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

// --- the 30-degree rule -------------------------------------------------------
// A rolling cue ball (w_xy = (0, v/R)) cut at t leaves with v' (after_impact)
// and keeps its topspin, then slides until u = 0: the final velocity is
// v' - (2/7) u0, u0 = v' - v x: v_f = (5/7) v' + (2/7) v x.  With mu = 0 that
// is v_f = v sin(t) t^ + k v cos(t) n^, k = (5 (1 - e)/2 + 2) / 7 =
// (9 - 5e)/14, so tan(deflection) = (1 - k) sin t cos t / (sin^2 t + k cos^2 t),
// which for e = 1 (k = 2/7) is the textbook sin t cos t / (sin^2 t + 2/5).
double deflection(double cut, double e, double mu) {
    double vx, vy;
    after_impact(1, cut, e, mu, vx, vy);
    return degrees(std::atan2(5.0 / 7 * vy, 5.0 / 7 * vx + 2.0 / 7));
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
            const demo::Setup rack = demo::set_up(c.scene, c.table, 0, rng.next());
            c.placements.push_back({0, kBallRadius + rng.uniform() * (0.25 * table.length - kBallRadius),
                                    kBallRadius + rng.uniform() * (table.width - kBallDiameter)});
            for (size_t i = 1; i < rack.balls.size(); ++i)
                c.placements.push_back({rack.balls[i].number, rack.balls[i].x, rack.balls[i].y});
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
    std::printf("# english off a rail\n");
    english(c);
    std::printf("# integrity\n");
    random_shots(shots, seed);
    return demo_tests::check_summary("test_physics");
}
