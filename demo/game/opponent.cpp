/* SPDX-License-Identifier: MIT */
// opponent.cpp - see opponent.h.  Geometry of the ghost ball: to send an
// object ball at B towards an aim point P, the cue ball must touch it with
// the line of centres along u = (P - B)/|P - B|, its centre then at
// G = B - 2R u; the cue ball travelling from C along (G - C) meets it there
// if nothing is in the way, and the cut angle is the angle between (G - C)
// and u.  A path from A to B of a ball of radius R is clear when every other
// ball's centre is at least 2R from the segment AB.
#include "game/opponent.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include "pool/det_math.h"

namespace demo {

namespace {

// The calling thread's CPU time, s (wall time misleads on a shared machine).
double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

constexpr double kMaxCutDeg = 75;
constexpr double kWin = 1e6, kFoulScore = -1000, kUnsettled = -1e5;
constexpr double kKeepTurn = 100, kPositionWeight = 50, kSafetyWeight = 20;
constexpr double kAngleError = 0.25, kSpeedError = 0.04;  // degrees, fraction (uniform +-)
constexpr double kBreakSpeed = 12;
const double kPotSpeeds[] = {1.2, 2.0, 3.0, 4.5};
const double kSafetySpeeds[] = {2.0, 4.0};
struct Tip {
    double side, topback;
};
const Tip kTips[] = {{0, 0}, {0, 0.35}, {0, -0.35}, {-0.3, 0}, {0.3, 0}};  // centre, follow, draw, left, right
const double kPlaceDistances[] = {0.25, 0.45};     // ball in hand, behind the ghost ball
// Position play (Search::Position): the kDeepened best candidates that keep
// the table are weighed again by the shooter's best next shot from where
// they leave the balls, tried on the kNextLines easiest potting lines at 3
// speeds and 3 tips (position_value).
constexpr int kDeepened = 4;
constexpr size_t kNextLines = 3;
constexpr double kNextWeight = 100;
const double kNextSpeeds[] = {1.2, 2.0, 3.0};
const Tip kNextTips[] = {{0, 0}, {0, 0.35}, {0, -0.35}};  // centre, follow, draw

// Where a ball aims to enter a pocket: a third of the way from the middle of
// the mouth to the hole's centre.
Point aim_point(const Pocket &p) {
    const double mx = 0.5 * (p.mouth[0].x + p.mouth[1].x), my = 0.5 * (p.mouth[0].y + p.mouth[1].y);
    return {mx + (p.x - mx) / 3, my + (p.y - my) / 3};
}

double distance_to_segment(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / len2, 0.0, 1.0) : 0.0;
    return det_hypot(px - (ax + t * dx), py - (ay + t * dy));
}

// No ball but `skip_a` and `skip_b` (numbers) within 2R of the segment.
bool clear_path(const std::vector<Ball> &balls, double ax, double ay, double bx, double by, int skip_a, int skip_b) {
    return std::none_of(balls.begin(), balls.end(), [&](const Ball &b) {
        return b.active && b.number != skip_a && b.number != skip_b &&
               distance_to_segment(b.x, b.y, ax, ay, bx, by) < kBallDiameter * 1.02;
    });
}

const Ball *cue_of(const std::vector<Ball> &balls) {
    for (const Ball &b : balls)
        if (b.number == 0) return &b;
    return nullptr;
}

// A potting line: the cue ball's aim to pot `target` in a pocket.
struct Line {
    int target;
    double angle_deg, cut_deg, distance;  // distance: cue ball to ghost plus ball to pocket
    double ghost_x, ghost_y, ux, uy;      // ghost ball and the object ball's unit direction
};

// The clear potting lines from (cx, cy); lines_for_ball limits them to one
// target (-1: every legal target).
std::vector<Line> potting_lines(const GameState &state, const Table &table, const std::vector<Ball> &balls, double cx,
                                double cy, bool need_cue_path) {
    std::vector<Line> lines;
    for (const Ball &b : balls) {
        if (!b.active || !legal_target(state, b.number, balls)) continue;
        for (const Pocket &p : table.pockets) {
            const Point a = aim_point(p);
            const double to_pocket = det_hypot(a.x - b.x, a.y - b.y);
            if (to_pocket < 1e-9) continue;
            const double ux = (a.x - b.x) / to_pocket, uy = (a.y - b.y) / to_pocket;
            const double gx = b.x - kBallDiameter * ux, gy = b.y - kBallDiameter * uy;
            const double cue_len = det_hypot(gx - cx, gy - cy);
            if (need_cue_path && cue_len < 1e-9) continue;
            const double cut = need_cue_path ? det_acos(std::clamp(((gx - cx) * ux + (gy - cy) * uy) / cue_len, -1.0, 1.0)) * 180 / M_PI : 0;
            if (cut > kMaxCutDeg) continue;
            if (!clear_path(balls, b.x, b.y, a.x, a.y, b.number, 0)) continue;
            if (need_cue_path && !clear_path(balls, cx, cy, gx, gy, 0, b.number)) continue;
            lines.push_back(Line{b.number, det_atan2(gy - cy, gx - cx) * 180 / M_PI, cut, cue_len + to_pocket, gx, gy, ux, uy});
        }
    }
    return lines;
}

double ease(const Line &l) { return det_cos(l.cut_deg * M_PI / 180) / (1 + l.distance); }

struct Candidate {
    Shot shot;
    bool place_cue;
    Point cue;
};

// Every candidate from the cue ball where it is.
std::vector<Candidate> candidates_from_cue(const GameState &state, const Table &table, const std::vector<Ball> &balls) {
    std::vector<Candidate> out;
    const Ball *cue = cue_of(balls);
    if (!cue || !cue->active) return out;
    for (const Line &l : potting_lines(state, table, balls, cue->x, cue->y, true))
        for (double v : kPotSpeeds)
            for (const Tip &tip : kTips) out.push_back(Candidate{Shot{l.angle_deg, v, tip.side, tip.topback}, false, {0, 0}});
    for (const Ball &b : balls) {
        if (!b.active || !legal_target(state, b.number, balls)) continue;
        const double dx = b.x - cue->x, dy = b.y - cue->y, d = det_hypot(dx, dy);
        if (d < kBallDiameter) continue;
        const double centre = det_atan2(dy, dx) * 180 / M_PI, half = det_asin(std::min(1.0, kBallRadius / d)) * 180 / M_PI;
        for (double offset : {0.0, -half, half})
            for (double v : kSafetySpeeds) out.push_back(Candidate{Shot{centre + offset, v, 0, 0}, false, {0, 0}});
    }
    return out;
}

// Ball in hand: the cue ball straight behind each potting line.
std::vector<Candidate> candidates_in_hand(const GameState &state, const Table &table, const std::vector<Ball> &balls) {
    std::vector<Candidate> out;
    std::vector<Ball> without_cue = balls;
    for (Ball &b : without_cue)
        if (b.number == 0) b.active = false;
    for (const Line &l : potting_lines(state, table, without_cue, 0, 0, false))
        for (double d : kPlaceDistances) {
            const Point c{l.ghost_x - d * l.ux, l.ghost_y - d * l.uy};
            if (!cue_placement_ok(table, without_cue, c.x, c.y) ||
                !clear_path(without_cue, c.x, c.y, l.ghost_x, l.ghost_y, 0, l.target))
                continue;
            const double angle = det_atan2(l.uy, l.ux) * 180 / M_PI;
            for (double v : kPotSpeeds)
                for (const Tip &tip : kTips) out.push_back(Candidate{Shot{angle, v, tip.side, tip.topback}, true, c});
        }
    return out;
}

// The table with the cue ball placed at p (at rest, on the table).
std::vector<Ball> with_cue_at(const std::vector<Ball> &balls, Point p) {
    std::vector<Ball> out = balls;
    for (Ball &b : out)
        if (b.number == 0) b = Ball{p.x, p.y, 0, 0, 0, true};
    return out;
}

// Whether the events of a shot so far (the strike first; from: the table
// before it) already make it a foul or a loss, whatever else happens: the
// cue ball pocketed (a scratch), its first contact with a ball not
// `state`'s shooter may hit first, the 8 pocketed before the group is
// cleared in 8-ball (rules.cpp: foul_of, apply_shot).  Each such shot scores
// kFoulScore or less (a loss, a foul, or unsettled below that).  (8: the
// eight ball, rules.cpp's kEight.)  `seen`
// carries the events already read and the first contact across calls.
struct Doom {
    size_t seen = 0;
    bool hit = false;
    bool check(const GameState &state, const std::vector<Ball> &from, const std::vector<Event> &events) {
        const bool eight = state.game == GameKind::EightBall, on_the_eight = eight && group_cleared(state, from);
        for (; seen < events.size(); ++seen) {
            const Event &e = events[seen];
            const int n = from[static_cast<size_t>(e.ball)].number;
            if (e.kind == EventKind::Pocket && (n == 0 || (eight && n == 8 && !on_the_eight))) return true;
            if (e.kind == EventKind::BallBall && n == 0 && !hit) {
                hit = true;
                if (!legal_target(state, from[static_cast<size_t>(e.other)].number, from)) return true;
            }
        }
        return false;
    }
};

// The score of a shot from `from` whose run is `out` (see opponent.h); next
// gets the rules' state after it.
double score_of(const GameState &state, const Table &table, const std::vector<Ball> &from, const ShotOutcome &out,
                GameState &next) {
    next = state;
    const Verdict v = apply_shot(next, shot_facts(out.events, from), from);
    if (!out.settled) return kUnsettled;
    if (v.winner >= 0) return v.winner == state.turn ? kWin : -kWin;
    if (v.foul != Foul::None) return kFoulScore;
    if (v.keeps_turn) return kKeepTurn + kPositionWeight * best_ease(next, table, out.balls);
    return -kSafetyWeight * best_ease(next, table, out.balls);
}

// A run of shot c from `from`; once `best` is kFoulScore or more, a run
// bound to foul or lose is ended (out.stopped: it cannot beat best).
ShotOutcome run(const SimConfig &config, const GameState &state, const std::vector<Ball> &from, const Shot &shot,
                double best) {
    Doom doom;
    return best >= kFoulScore
               ? simulate_shot(config, from, shot,
                               [&](const std::vector<Event> &events) { return doom.check(state, from, events); })
               : simulate_shot(config, from, shot);
}

}  // namespace

double position_value(const SimConfig &config, const Table &table, const GameState &state,
                      const std::vector<Ball> &balls, int *tried) {
    const Ball *cue = cue_of(balls);
    if (tried) *tried = 0;
    if (!cue || !cue->active) return 0;
    std::vector<Line> lines = potting_lines(state, table, balls, cue->x, cue->y, true);
    std::stable_sort(lines.begin(), lines.end(), [](const Line &a, const Line &b) { return ease(a) > ease(b); });
    if (lines.size() > kNextLines) lines.resize(kNextLines);
    double best = -INFINITY;
    for (const Line &l : lines)
        for (double v : kNextSpeeds)
            for (const Tip &tip : kNextTips) {
                if (best >= kWin) break;
                const Shot shot{l.angle_deg, v, tip.side, tip.topback};
                const ShotOutcome out = run(config, state, balls, shot, best);
                if (tried) ++*tried;
                if (out.stopped) continue;
                GameState next;
                best = std::max(best, score_of(state, table, balls, out, next));
            }
    if (best >= kWin) return 1;
    if (best >= kKeepTurn) return 0.5 + 0.5 * std::min(1.0, (best - kKeepTurn) / kPositionWeight);
    return 0;
}

double with_position(double score, double value) { return score + kNextWeight * value; }

double best_ease(const GameState &state, const Table &table, const std::vector<Ball> &balls) {
    const Ball *cue = cue_of(balls);
    if (!cue || !cue->active) return 0;
    double best = 0;
    for (const Line &l : potting_lines(state, table, balls, cue->x, cue->y, true)) best = std::max(best, ease(l));
    return best;
}

Opponent::Opponent(const SimConfig &config, uint64_t seed, Search search)
    : config_(config), table_(scene_table(config.scene, config.table)), rng_(seed ^ 0x6f70706f6e656e74ULL),
      search_(search) {
    if (config_.broadphase == WorldBroadphase::Tree) config_.broadphase = WorldBroadphase::List;
}

Plan Opponent::choose(const GameState &state, const std::vector<Ball> &balls) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_seconds();
    Plan plan;
    if (state.breaking) {
        plan.shot = Shot{0, kBreakSpeed};
        const Ball *cue = cue_of(balls);
        for (const Ball &b : balls)
            if (b.number == 1 && b.active && cue) plan.shot.angle_deg = det_atan2(b.y - cue->y, b.x - cue->x) * 180 / M_PI;
    } else {
        std::vector<Candidate> cands = state.ball_in_hand ? candidates_in_hand(state, table_, balls) : std::vector<Candidate>{};
        const Ball *cue = cue_of(balls);
        Point spot{cue ? cue->x : 0, cue ? cue->y : 0};
        if (state.ball_in_hand && (!cue || !cue->active || !cue_placement_ok(table_, balls, spot.x, spot.y)))
            spot = free_head_spot(table_, balls);
        const std::vector<Ball> here = state.ball_in_hand ? with_cue_at(balls, spot) : balls;
        for (Candidate c : candidates_from_cue(state, table_, here)) {
            c.place_cue = state.ball_in_hand;
            c.cue = spot;
            cands.push_back(c);
        }
        // nothing at all to try (never on a legal table): roll the cue ball up the table
        plan.shot = Shot{0, 1.0};
        plan.place_cue = state.ball_in_hand;
        plan.cue = spot;
        double best = -INFINITY;
        // Two cuts that never change the choice (a later candidate replaces
        // the best only with a strictly higher score): once a win is found
        // nothing can beat it, and once a shot scoring kFoulScore or more is
        // found a run bound to foul or lose (Doom) is ended at once.  (Position
        // play only raises the scores of shots that keep the table, which stay
        // below kWin: both cuts hold.)
        std::vector<double> score(cands.size(), -INFINITY);
        struct Kept {
            size_t index;
            GameState next;
            std::vector<Ball> balls;
        };
        std::vector<Kept> kept;  // the candidates that keep the table, for position play
        for (size_t k = 0; k < cands.size(); ++k) {
            const Candidate &c = cands[k];
            if (best >= kWin) break;
            const std::vector<Ball> from = c.place_cue ? with_cue_at(balls, c.cue) : balls;
            const ShotOutcome out = run(config_, state, from, c.shot, best);
            if (out.stopped) continue;
            GameState next;
            score[k] = score_of(state, table_, from, out, next);
            if ((score[k] >= kKeepTurn && score[k] < kWin) || (score[k] > kFoulScore && score[k] <= 0))
                kept.push_back(Kept{k, next, out.balls});
            best = std::max(best, score[k]);
        }
        if (search_ == Search::Position && best < kWin) {
            // the kDeepened best that keep the table (ties: the earlier),
            // weighed again by the shooter's next shot; if none keeps it, the
            // kDeepened best safeties by the opponent's next shot
            const bool keeping = best >= kKeepTurn;
            kept.erase(std::remove_if(kept.begin(), kept.end(),
                                      [&](const Kept &d) { return (score[d.index] >= kKeepTurn) != keeping; }),
                       kept.end());
            std::stable_sort(kept.begin(), kept.end(),
                             [&](const Kept &a, const Kept &b) { return score[a.index] > score[b.index]; });
            if (kept.size() > static_cast<size_t>(kDeepened)) kept.resize(kDeepened);
            for (const Kept &d : kept) {
                int tried = 0;
                const double value = position_value(config_, table_, d.next, d.balls, &tried);
                score[d.index] = keeping ? with_position(score[d.index], value) : score[d.index] - kNextWeight * value;
                plan.candidates += tried;
            }
        }
        best = -INFINITY;
        for (size_t k = 0; k < cands.size(); ++k)
            if (score[k] > best) {
                best = score[k];
                plan.shot = cands[k].shot;
                plan.place_cue = cands[k].place_cue;
                plan.cue = cands[k].cue;
                plan.score = score[k];
            }
        plan.candidates += static_cast<int>(cands.size());
    }
    plan.shot.angle_deg += kAngleError * (2 * rng_.uniform() - 1);
    plan.shot.speed = std::min(kMaxShotSpeed, plan.shot.speed * (1 + kSpeedError * (2 * rng_.uniform() - 1)));
    plan.think_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    plan.cpu_seconds = thread_cpu_seconds() - cpu_start;
    return plan;
}

}  // namespace demo
