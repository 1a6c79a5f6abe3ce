/* SPDX-License-Identifier: MIT */
// exact_engine.cpp - see exact_engine.h.
//
// Each ball's motion is a Track (motion.h): from its start t0 its position
// is p0 + v0 h + a h^2 / 2 (h = t - t0) until its next state change t_end.
// Tracks are never re-based by frames: a frame only samples them, so the
// simulation does not depend on the frame rate.  Events, in time order:
//   ball-ball  the earliest t in [0, horizon] at which two balls touch while
//              approaching, c2d_time_of_impact_accel (frictionless scenes:
//              c2d_time_of_impact), with the horizon no later than either
//              ball's next state change or swept box's end;
//   cushion    a face (rails, jaw facings) with unit normal n at a is hit
//              when the gap g(h) = (p(h) - a).n - R = g0 + g1 h + g2 h^2
//              (g1 = v.n, g2 = a.n / 2) falls through 0 (g' < 0) with the
//              contact point on the face; roots by the stable formulas
//              q = -(g1 + sign(g1) sqrt(g1^2 - 4 g2 g0)) / 2, q / g2, g0 / q;
//   jaw nose   an immovable disk of radius r: c2d_time_of_impact_accel with
//              radius sum R + r;
//   pocket     the ball's centre enters the hole: radius sum = hole radius;
//   transition the track's end (slide -> roll, roll -> spin or stop,
//              spin -> stop).
// Impacts: c2d_collide_rough between balls (disk spin = wz: the equator's
// slip is horizontal, wx and wy are untouched), c2d_collide_rough_normal
// against a cushion face (an immovable wall: mass and inertia INFINITY,
// radius 0), c2d_collide_rough against a nose (immovable disk); the
// frictionless scenes use c2d_collide and c2d_collide_normal.  Contacts
// slower than Model::absorb_below are absorbed rather than bounced (model.h):
// the velocities are projected onto those that approach nothing a ball
// touches (the nearest point of a convex cone: the velocity itself, its
// projection on one contact's line, or the corner of two), and pairs that
// their accelerations press together end their slides or move on as one.
// Each ball's proxy in the broadphase (broadphase.h: Box2D's dynamic tree, or
// for the gas a uniform grid) covers its path (the box of a
// quadratic: its ends and, where a velocity component changes sign, the
// turning point) over a horizon of a few diameters; a ball re-queries the
// tree when its motion changes or its horizon runs out, so a pair is always
// found by whichever of the two swept last.  An event carries the generations of its
// balls; a ball's generation is bumped whenever its motion changes, so an
// event a later change made stale is skipped when it comes up.
#include "pool/exact_engine.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

#include "pool/broadphase.h"
#include "pool/event_queue.h"
#include "pool/slow_contact.h"

extern "C" {
#include "collide2d.h"
}

namespace demo {

namespace {

b2AABB box_of(double x0, double y0, double x1, double y1) {
    b2AABB box;
    box.lowerBound.Set(static_cast<float>(x0 * kUnitsPerMetre), static_cast<float>(y0 * kUnitsPerMetre));
    box.upperBound.Set(static_cast<float>(x1 * kUnitsPerMetre), static_cast<float>(y1 * kUnitsPerMetre));
    // float rounding of the bounds must never shrink the box
    const float pad = 1e-4f;
    box.lowerBound -= b2Vec2(pad, pad);
    box.upperBound += b2Vec2(pad, pad);
    return box;
}

b2AABB box_of_disk(double x, double y, double r) { return box_of(x - r, y - r, x + r, y + r); }

// The range of x0 + v h + a h^2 / 2 over h in [0, horizon].
void quadratic_range(double x0, double v, double a, double horizon, double &lo, double &hi) {
    const double x1 = x0 + v * horizon + 0.5 * a * horizon * horizon;
    lo = std::min(x0, x1);
    hi = std::max(x0, x1);
    if (a != 0) {
        const double turn = -v / a;
        if (turn > 0 && turn < horizon) {
            const double xt = x0 + 0.5 * v * turn;
            lo = std::min(lo, xt);
            hi = std::max(hi, xt);
        }
    }
}

// The earliest h in [0, horizon] at which g0 + g1 h + g2 h^2 falls through
// 0 (or is <= 0 and falling at h = 0); -1 if none.
double earliest_entry(double g0, double g1, double g2, double horizon) {
    if (g0 <= 0 && g1 < 0) return 0;
    double h = -1;
    if (g2 == 0) {
        if (g1 < 0) h = g0 / -g1;
    } else {
        const double disc = g1 * g1 - 4 * g2 * g0;
        if (disc <= 0) return -1;  // no crossing, or a graze
        const double q = -0.5 * (g1 + std::copysign(std::sqrt(disc), g1));
        const double r1 = q / g2, r2 = g0 / q;
        // opening up: the falling root is the smaller; opening down, the larger
        h = g2 > 0 ? std::min(r1, r2) : std::max(r1, r2);
    }
    return h >= 0 && h <= horizon ? h : -1;
}

c2d_body body_of(const Ball &b) { return c2d_body{{b.x, b.y}, {b.vx, b.vy}, kBallMass}; }
c2d_body static_body(double x, double y) { return c2d_body{{x, y}, {0, 0}, INFINITY}; }
c2d_disk disk_of(const Ball &b) {
    return c2d_disk{{b.x, b.y}, {b.vx, b.vy}, b.wz, kBallMass, kBallRadius, kBallInertia};
}
c2d_disk static_disk(double x, double y, double r) { return c2d_disk{{x, y}, {0, 0}, 0, INFINITY, r, INFINITY}; }

enum ProxyKind { kBallProxy = 0, kWallProxy = 1, kNoseProxy = 2, kHoleProxy = 3 };
constexpr int kTransition = 4;    // event kind: a ball's track ends
constexpr int kSweepExpires = 5;  // event kind: a ball's swept box runs out

struct Pending {
    double t;
    int a, kind, b;
    unsigned gen_a, gen_b;
    bool operator>(const Pending &o) const {
        if (t != o.t) return t > o.t;
        if (a != o.a) return a > o.a;
        if (kind != o.kind) return kind > o.kind;
        return b > o.b;
    }
};

// A face a ball can hit: a rail's cushion or a jaw's facing.
struct Wall {
    Segment s;
    EventKind kind;
    int feature;
};

struct Nose {
    double x, y, r;
    int feature;
};

class ExactEngine : public Engine {
public:
    ExactEngine(const std::vector<Ball> &balls, const Table &table, const Model &model, bool cell_grid);
    void step(double dt, Stats &stats, FrameLog &log) override;
    bool settle(double max_seconds, Stats &stats, FrameLog &log) override;
    void set_motion(int i, const Ball &state) override;
    void place_ball(int i, Point p) override;
    double now() const override { return now_; }

private:
    void insert_statics();
    void insert_ball(int i);
    bool translating(int i) const;
    Ball at(int i, double t) const { return state_at(track_[static_cast<size_t>(i)], t); }
    void sweep(int i);
    void mark_changed(int i);
    void find_events_of_changed();
    bool leaves_pair_to(int i, int j) const;
    void find_events(int i);
    void event_with_ball(int i, int j);
    void event_with_wall(int i, int w);
    void event_with_disk(int i, double x, double y, double radius_sum, int kind, int index);
    void push(double t, int i, int kind, int b, double limit);
    void start_track(int i, const Ball &b, double t);
    void motion_changed(int i);
    void remove(int i);
    void restart();
    bool process(double t_limit, long budget, Stats &stats, FrameLog &log);
    bool resolve(const Pending &e, Stats &stats, FrameLog &log);
    bool resolve_balls(const Pending &e, Stats &stats, FrameLog &log);
    bool resolve_fixed(const Pending &e, Stats &stats, FrameLog &log);
    void pocket(const Pending &e, Stats &stats, FrameLog &log);
    void transition(const Pending &e, FrameLog &log);
    void log_event(FrameLog &log, double t, EventKind kind, int ball, int other, int feature, double impulse) const;
    void sample(double t);
    void log_waypoint(FrameLog &log, int i) const;
    Motion motion_of(const Ball &b) const;
    // How an impact approaching at this speed is treated.
    enum class Contact { Absorbed, Impact };
    Contact contact(double approach) const;
    void limits_of(int i, double t, const Ball &b, std::vector<Limit> &out);
    Ball absorbed(int i, double t);
    void pressed_group(int a, int b, double t, std::vector<int> &group);
    bool move_together(int a, int b, double t);
    double closing_by_acceleration(int a, int b, double t) const;

    const Model model_;
    std::vector<Wall> walls_;
    std::vector<Nose> noses_;
    std::vector<Pocket> holes_;
    std::vector<Track> track_;
    std::vector<double> horizon_;    // end of the ball's swept box
    std::vector<unsigned> gen_;      // bumped whenever a ball's motion changes
    std::vector<int> changed_;       // balls changed from outside since the last step
    std::vector<char> is_changed_;
    std::vector<int32> proxy_;
    std::vector<b2AABB> swept_;
    std::unique_ptr<Broadphase> broad_;
    EventQueue<Pending> queue_{kFrameDt / 4};  // buckets of a quarter frame
    double now_ = 0;
    bool record_paths_ = true;       // waypoints and contacts for the checker
    std::vector<uintptr_t> hits_;    // the tags a query found
    std::vector<Limit> limits_;
    std::vector<int> group_;
    std::vector<int> moved_;         // balls given a new track by the event being resolved
};

// A proxy's tag: what it is and which.
uintptr_t tag(int kind, int index) { return static_cast<uintptr_t>(index) * 4 + static_cast<uintptr_t>(kind); }

// The grid's cells: three and a half diameters, a little more than a swept
// box (two diameters of travel plus one, sweep()), so almost every box is
// one cell's; its region is the table and its rails, where every ball stays.
std::unique_ptr<Broadphase> broadphase_for(const Table &table, bool cell_grid) {
    if (!cell_grid) return make_dynamic_tree();
    return make_cell_grid(box_of(-table.rail, -table.rail, table.length + table.rail, table.width + table.rail),
                          static_cast<float>(3.5 * kBallDiameter * kUnitsPerMetre));
}

ExactEngine::ExactEngine(const std::vector<Ball> &balls, const Table &table, const Model &model, bool cell_grid)
    : Engine(balls), model_(model), broad_(broadphase_for(table, cell_grid)) {
    for (size_t c = 0; c < table.cushions.size(); ++c)
        walls_.push_back(Wall{table.cushions[c], EventKind::Cushion, static_cast<int>(c)});
    for (size_t p = 0; p < table.pockets.size(); ++p) {
        const Pocket &k = table.pockets[p];
        holes_.push_back(k);
        for (int j = 0; j < 2; ++j) {
            const int feature = static_cast<int>(p) * 2 + j;
            walls_.push_back(Wall{k.jaws[j].facing, EventKind::Jaw, feature});
            noses_.push_back(Nose{k.jaws[j].nose_x, k.jaws[j].nose_y, k.jaws[j].nose_r, feature});
        }
    }
    const size_t n = balls.size();
    track_.resize(n);
    horizon_.assign(n, 0.0);
    gen_.assign(n, 0u);
    proxy_.assign(n, b2_nullNode);
    swept_.resize(n);
    is_changed_.assign(n, 0);
    insert_statics();
    for (size_t i = 0; i < n; ++i) {
        Ball &b = balls_[i];
        if (!model_.friction) b.wx = b.wy = b.wz = 0;
        b.motion = motion_of(b);
        track_[i] = make_track(b, 0, model_.cloth, model_.friction);
        insert_ball(static_cast<int>(i));
    }
    restart();
}

void ExactEngine::insert_statics() {
    for (size_t w = 0; w < walls_.size(); ++w) {
        const Segment &s = walls_[w].s;
        broad_->add(box_of(std::min(s.ax, s.bx), std::min(s.ay, s.by), std::max(s.ax, s.bx), std::max(s.ay, s.by)),
                          tag(kWallProxy, static_cast<int>(w)));
    }
    for (size_t k = 0; k < noses_.size(); ++k)
        broad_->add(box_of_disk(noses_[k].x, noses_[k].y, noses_[k].r), tag(kNoseProxy, static_cast<int>(k)));
    for (size_t p = 0; p < holes_.size(); ++p)
        broad_->add(box_of_disk(holes_[p].x, holes_[p].y, holes_[p].capture_radius), tag(kHoleProxy, static_cast<int>(p)));
}

void ExactEngine::insert_ball(int i) {
    const size_t k = static_cast<size_t>(i);
    const Ball &b = balls_[k];
    if (proxy_[k] != b2_nullNode || !b.active) return;
    horizon_[k] = INFINITY;
    swept_[k] = box_of_disk(b.x, b.y, kBallRadius);
    proxy_[k] = broad_->add(swept_[k], tag(kBallProxy, i));
}

bool ExactEngine::translating(int i) const {
    const Track &k = track_[static_cast<size_t>(i)];
    return k.start.active && (k.start.vx != 0 || k.start.vy != 0 || k.ax != 0 || k.ay != 0);
}

// The box spans the path until the ball has gone some two diameters (at
// least a frame, at most a second) or its track ends, so fast balls re-query
// often and slow ones rarely.  With speed s and acceleration a along the
// path, 2D is covered after h = 4D / (s + sqrt(s^2 + 4 a D)).
void ExactEngine::sweep(int i) {
    const size_t k = static_cast<size_t>(i);
    const Track &tr = track_[k];
    if (!translating(i)) {
        const Ball b = at(i, now_);
        horizon_[k] = INFINITY;
        swept_[k] = box_of_disk(b.x, b.y, kBallRadius);
    } else {
        const Ball b = at(i, now_);
        const double s = std::hypot(b.vx, b.vy), a = std::hypot(tr.ax, tr.ay);
        const double wanted = std::min(1.0, std::max(kFrameDt, 4 * kBallDiameter / (s + std::sqrt(s * s + 4 * a * kBallDiameter))));
        const double h = std::min(wanted, tr.t_end - now_);
        double x0, x1, y0, y1;
        quadratic_range(b.x, b.vx, tr.ax, h, x0, x1);
        quadratic_range(b.y, b.vy, tr.ay, h, y0, y1);
        swept_[k] = box_of(x0 - kBallRadius, y0 - kBallRadius, x1 + kBallRadius, y1 + kBallRadius);
        horizon_[k] = now_ + h;
        // the track's end renews the box itself
        if (wanted < tr.t_end - now_) queue_.push(Pending{now_ + h, i, kSweepExpires, -1, gen_[k], 0u});
    }
    broad_->move(proxy_[k], swept_[k]);
}

// Events beyond `limit` are dropped: the box that runs out first is renewed
// before then, and its ball finds the event again.
void ExactEngine::push(double t, int i, int kind, int b, double limit) {
    if (t > limit) return;
    const unsigned gb = kind == kBallProxy ? gen_[static_cast<size_t>(b)] : 0u;
    queue_.push(Pending{t, i, kind, b, gen_[static_cast<size_t>(i)], gb});
}

void ExactEngine::event_with_ball(int i, int j) {
    const size_t ki = static_cast<size_t>(i), kj = static_cast<size_t>(j);
    if (!balls_[kj].active || (!translating(i) && !translating(j))) return;
    const double limit = std::min(horizon_[ki], horizon_[kj]);
    const c2d_body a = body_of(at(i, now_)), b = body_of(at(j, now_));
    double t;
    c2d_status status;
    if (model_.friction) {
        const Track &ti = track_[ki], &tj = track_[kj];
        status = c2d_time_of_impact_accel(&a, c2d_vec2{ti.ax, ti.ay}, &b, c2d_vec2{tj.ax, tj.ay}, kBallDiameter,
                                          limit - now_, &t);
    } else {
        status = c2d_time_of_impact(&a, &b, kBallDiameter, &t);
    }
    if (status == C2D_OK) push(now_ + t, i, kBallProxy, j, limit);
}

void ExactEngine::event_with_wall(int i, int w) {
    const Segment &s = walls_[static_cast<size_t>(w)].s;
    const Track &tr = track_[static_cast<size_t>(i)];
    const Ball b = at(i, now_);
    const double limit = horizon_[static_cast<size_t>(i)];
    const double g0 = (b.x - s.ax) * s.nx + (b.y - s.ay) * s.ny - kBallRadius;
    const double h = earliest_entry(g0, b.vx * s.nx + b.vy * s.ny, 0.5 * (tr.ax * s.nx + tr.ay * s.ny), limit - now_);
    if (h < 0) return;
    double x, y;
    position_at(tr, now_ + h, x, y);
    const double ex = s.bx - s.ax, ey = s.by - s.ay;
    const double along = (x - s.ax) * ex + (y - s.ay) * ey;
    if (along < 0 || along > ex * ex + ey * ey) return;  // beyond the face: a nose or another face takes it
    push(now_ + h, i, kWallProxy, w, limit);
}

// A fixed disk: a jaw's nose (radius sum R + r) or a hole (the centre
// entering it: radius sum = the hole's radius).
void ExactEngine::event_with_disk(int i, double x, double y, double radius_sum, int kind, int index) {
    const Track &tr = track_[static_cast<size_t>(i)];
    const double limit = horizon_[static_cast<size_t>(i)];
    const c2d_body a = body_of(at(i, now_)), p = static_body(x, y);
    double t;
    const c2d_status status = model_.friction
                                  ? c2d_time_of_impact_accel(&a, c2d_vec2{tr.ax, tr.ay}, &p, c2d_vec2{0, 0}, radius_sum,
                                                             limit - now_, &t)
                                  : c2d_time_of_impact(&a, &p, radius_sum, &t);
    if (status == C2D_OK) push(now_ + t, i, kind, index, limit);
}

// Ball i's motion changed (or its box ran out): the events with everything
// its box meets.  A ball that has just stopped looks too: the moving balls'
// events with it were found on its old track and are stale now.
void ExactEngine::find_events(int i) {
    hits_.clear();
    broad_->query(swept_[static_cast<size_t>(i)], hits_);
    for (uintptr_t t : hits_) {
        const int kind = static_cast<int>(t & 3u), index = static_cast<int>(t >> 2);
        const size_t k = static_cast<size_t>(index);
        switch (kind) {
        case kBallProxy:
            if (index != i && !leaves_pair_to(i, index)) event_with_ball(i, index);
            break;
        case kWallProxy: event_with_wall(i, index); break;
        case kNoseProxy: event_with_disk(i, noses_[k].x, noses_[k].y, kBallRadius + noses_[k].r, kind, index); break;
        default: event_with_disk(i, holes_[k].x, holes_[k].y, holes_[k].capture_radius, kind, index);
        }
    }
}

// A new track for ball i from time t, its generation bumped, its box
// renewed and its state change queued.
void ExactEngine::start_track(int i, const Ball &b, double t) {
    track_[static_cast<size_t>(i)] = make_track(b, t, model_.cloth, model_.friction);
    motion_changed(i);
    if (std::find(moved_.begin(), moved_.end(), i) == moved_.end()) moved_.push_back(i);
}

void ExactEngine::motion_changed(int i) {
    const size_t k = static_cast<size_t>(i);
    ++gen_[k];
    sweep(i);
    const double end = track_[k].t_end;
    if (end < INFINITY) queue_.push(Pending{end, i, kTransition, -1, gen_[k], 0u});
}

void ExactEngine::remove(int i) {
    const size_t k = static_cast<size_t>(i);
    Ball &b = balls_[k];
    b = at(i, now_);
    b.vx = b.vy = b.wx = b.wy = b.wz = 0;
    b.active = false;
    b.motion = Motion::Pocketed;
    track_[k] = make_track(b, now_, model_.cloth, model_.friction);
    broad_->remove(proxy_[k]);
    proxy_[k] = b2_nullNode;
    ++gen_[k];
}

// Forgets every event and finds them all again: at the start, and after a
// frame whose event budget ran out.
void ExactEngine::restart() {
    queue_.clear();
    for (size_t i = 0; i < balls_.size(); ++i) mark_changed(static_cast<int>(i));
    find_events_of_changed();
}

void ExactEngine::set_motion(int i, const Ball &state) {
    const size_t k = static_cast<size_t>(i);
    if (!balls_[k].active) return;
    Ball b = at(i, now_);
    b.vx = state.vx;
    b.vy = state.vy;
    if (model_.friction) {
        b.wx = state.wx;
        b.wy = state.wy;
        b.wz = state.wz;
    }
    b.motion = motion_of(b);
    balls_[k] = b;
    track_[k] = make_track(b, now_, model_.cloth, model_.friction);
    mark_changed(i);
}

void ExactEngine::place_ball(int i, Point p) {
    const size_t k = static_cast<size_t>(i);
    Ball &b = balls_[k];
    if (b.active) return;
    b = Ball{p.x, p.y, 0, 0, b.number, true};
    track_[k] = make_track(b, now_, model_.cloth, model_.friction);
    insert_ball(i);
    mark_changed(i);
}

// Changes from outside come between frames, several at once: they are
// collected, and their events found when the next frame starts, all balls
// swept first.
void ExactEngine::mark_changed(int i) {
    if (!balls_[static_cast<size_t>(i)].active || is_changed_[static_cast<size_t>(i)]) return;
    is_changed_[static_cast<size_t>(i)] = 1;
    changed_.push_back(i);
}

void ExactEngine::find_events_of_changed() {
    std::sort(changed_.begin(), changed_.end());
    for (int i : changed_) motion_changed(i);
    for (int i : changed_) find_events(i);
    for (int i : changed_) is_changed_[static_cast<size_t>(i)] = 0;
    changed_.clear();
}

// Of a pair changed together, one ball finds the pair's event, so it is not
// queued twice (the time seen from either ball can differ in the last bit):
// the moving one, or of two moving ones the lower index.  Two balls at rest
// never meet.
bool ExactEngine::leaves_pair_to(int i, int j) const {
    return is_changed_[static_cast<size_t>(j)] && translating(j) && (!translating(i) || j < i);
}

// The frictionless scenes have no rolling: a moving ball glides ("sliding").
Motion ExactEngine::motion_of(const Ball &b) const {
    if (model_.friction || !b.active) return classify(b);
    return b.vx != 0 || b.vy != 0 ? Motion::Sliding : Motion::Stationary;
}

ExactEngine::Contact ExactEngine::contact(double approach) const {
    if (!model_.friction) return Contact::Impact;
    return approach < model_.absorb_below ? Contact::Absorbed : Contact::Impact;
}

c2d_surface surface_of(const Surface &s) { return c2d_surface{s.restitution, s.friction, s.tangential_restitution}; }

void ExactEngine::log_event(FrameLog &log, double t, EventKind kind, int ball, int other, int feature,
                            double impulse) const {
    const Ball &b = kind == EventKind::Pocket ? balls_[static_cast<size_t>(ball)] : track_[static_cast<size_t>(ball)].start;
    log.events.push_back(Event{t, kind, ball, other, feature, b.x, b.y, b.vx, b.vy, b.wx, b.wy, b.wz, impulse});
}

// The constraints of everything ball i touches at time t (as it is then):
// other balls (moving away at their own speed along the line of centres)
// and fixed faces and noses.
void ExactEngine::limits_of(int i, double t, const Ball &b, std::vector<Limit> &out) {
    out.clear();
    const double reach = kBallDiameter * (1 + 1e-9);
    hits_.clear();
    broad_->query(box_of_disk(b.x, b.y, kBallRadius * (1 + 1e-9)), hits_);
    for (uintptr_t tg : hits_) {
        const int kind = static_cast<int>(tg & 3u), index = static_cast<int>(tg >> 2);
        const size_t k = static_cast<size_t>(index);
        if (kind == kBallProxy && index != i) {
            const Ball o = at(index, t);
            const double dx = o.x - b.x, dy = o.y - b.y, d = std::hypot(dx, dy);
            // a ball moving off lets b follow at its speed; one coming at b
            // is held back when it is absorbed itself, not b pushed away
            if (d > 0 && d <= reach) out.push_back(Limit{dx / d, dy / d, std::max(0.0, (o.vx * dx + o.vy * dy) / d)});
        } else if (kind == kWallProxy) {
            const Segment &w = walls_[k].s;
            const double ex = w.bx - w.ax, ey = w.by - w.ay, along = (b.x - w.ax) * ex + (b.y - w.ay) * ey;
            const double gap = (b.x - w.ax) * w.nx + (b.y - w.ay) * w.ny - kBallRadius;
            if (along >= 0 && along <= ex * ex + ey * ey && gap <= kBallDiameter * 1e-9) out.push_back(Limit{-w.nx, -w.ny, 0});
        } else if (kind == kNoseProxy) {
            const Nose &w = noses_[k];
            const double dx = w.x - b.x, dy = w.y - b.y, d = std::hypot(dx, dy);
            if (d <= (kBallRadius + w.r) * (1 + 1e-9)) out.push_back(Limit{dx / d, dy / d, 0});
        }
    }
}

// Ball i at time t after an absorbed contact (Model::absorb_below): its
// velocity becomes the nearest that approaches nothing it touches.  Left
// slower than absorb_below it stops (top and back spin too: a slow ball
// pressed into others would otherwise keep pushing).  Else, if its spin is
// at least rolling speed (R |w_xy| >= |v|), the contacts take its slip and
// it rolls (w_xy from v), else its spin's rolling velocity
// v_roll = R (wy, -wx), towards which friction pulls it, is limited the same
// way.  Energy only decreases.
Ball ExactEngine::absorbed(int i, double t) {
    Ball b = at(i, t);
    std::vector<Limit> &limits = limits_;
    limits_of(i, t, b, limits);
    nearest_within(b.vx, b.vy, limits);
    if (std::hypot(b.vx, b.vy) < model_.absorb_below) {
        b.vx = b.vy = 0;
        roll(b);
    } else if (kBallRadius * std::hypot(b.wx, b.wy) >= std::hypot(b.vx, b.vy)) {
        roll(b);
    } else {
        double rx = kBallRadius * b.wy, ry = -kBallRadius * b.wx;
        nearest_within(rx, ry, limits);
        b.wx = -ry / kBallRadius;
        b.wy = rx / kBallRadius;
        b.motion = motion_of(b);
    }
    return b;
}

// The balls in sustained contact with a and b at t: those touching them,
// directly or through others, and not moving apart along the line of
// centres faster than absorb_below.
void ExactEngine::pressed_group(int a, int b, double t, std::vector<int> &group) {
    group = {a, b};
    const double reach = kBallDiameter * (1 + 1e-9);
    for (size_t k = 0; k < group.size(); ++k) {
        const Ball m = at(group[k], t);
        hits_.clear();
        broad_->query(box_of_disk(m.x, m.y, reach), hits_);
        for (uintptr_t tg : hits_) {
            const int index = static_cast<int>(tg >> 2);
            if ((tg & 3u) != kBallProxy || std::find(group.begin(), group.end(), index) != group.end()) continue;
            const Ball o = at(index, t);
            const double dx = o.x - m.x, dy = o.y - m.y, d = std::hypot(dx, dy);
            if (d <= reach && ((o.vx - m.vx) * dx + (o.vy - m.vy) * dy) / d <= model_.absorb_below) group.push_back(index);
        }
    }
}

// A sustained contact: the accelerations press a and b together, so
// absorbing velocities alone would only bring them back into contact an
// instant later, again and again.  If any ball of the group in contact
// (pressed_group) slides, the sliding ones end their slides at once (the
// state each slide would end in: less energy); else the group moves on as
// one, every ball taking its mean velocity and z spin and rolling (momentum
// kept, energy lost).  Returns whether any ball changed.
bool ExactEngine::move_together(int a, int b, double t) {
    std::vector<int> &group = group_;
    pressed_group(a, b, t, group);
    bool changed = false;
    for (int m : group) {  // slides end
        const Ball before = at(m, t), s = slid(before);
        if (!same_motion(s, before)) {
            start_track(m, s, t);
            changed = true;
        }
    }
    if (closing_by_acceleration(a, b, t) <= 0) return changed;
    double vx = 0, vy = 0, wz = 0;  // all roll or stand: they move on as one
    for (int m : group) {
        const Ball s = at(m, t);
        vx += s.vx, vy += s.vy, wz += s.wz;
    }
    const double n = static_cast<double>(group.size());
    for (int m : group) {
        const Ball before = at(m, t);
        Ball s = before;
        s.vx = vx / n, s.vy = vy / n, s.wz = wz / n;
        roll(s);
        if (!same_motion(s, before)) {
            start_track(m, s, t);
            changed = true;
        }
    }
    return changed;
}

// How fast the accelerations of balls a and b (their current tracks) close
// their line of centres at time t, m/s^2 (> 0: pressing together).
double ExactEngine::closing_by_acceleration(int a, int b, double t) const {
    const Track &ta = track_[static_cast<size_t>(a)], &tb = track_[static_cast<size_t>(b)];
    double ax, ay, bx, by;
    position_at(ta, t, ax, ay);
    position_at(tb, t, bx, by);
    const double dx = bx - ax, dy = by - ay, d = std::hypot(dx, dy);
    return ((ta.ax - tb.ax) * dx + (ta.ay - tb.ay) * dy) / d;
}

// Returns whether the balls' motion changed.
bool ExactEngine::resolve_balls(const Pending &e, Stats &stats, FrameLog &log) {
    Ball a = at(e.a, e.t), b = at(e.b, e.t);
    const double dx = b.x - a.x, dy = b.y - a.y, d = std::hypot(dx, dy);
    const double nx = dx / d, ny = dy / d;
    const double vax = a.vx, vay = a.vy;
    if (contact((a.vx - b.vx) * nx + (a.vy - b.vy) * ny) == Contact::Absorbed) {
        // each ball in turn, against all it touches (the other one's new
        // state included)
        const Ball a0 = a, b0 = b;
        a = absorbed(e.a, e.t);
        if (!same_motion(a, a0)) start_track(e.a, a, e.t);
        b = absorbed(e.b, e.t);
        if (!same_motion(b, b0)) start_track(e.b, b, e.t);
        bool changed = !same_motion(a, a0) || !same_motion(b, b0);
        if (closing_by_acceleration(e.a, e.b, e.t) > 0) changed = move_together(e.a, e.b, e.t) || changed;
        if (!changed) return false;
    } else if (model_.friction) {
        c2d_disk da = disk_of(a), db = disk_of(b);
        if (c2d_collide_rough(&da, &db, surface_of(model_.ball)) != C2D_OK) return false;
        a.vx = da.vel.x, a.vy = da.vel.y, a.wz = da.spin;
        b.vx = db.vel.x, b.vy = db.vel.y, b.wz = db.spin;
        a.motion = motion_of(a);
        b.motion = motion_of(b);
        start_track(e.a, a, e.t);
        start_track(e.b, b, e.t);
    } else {
        c2d_body ba = body_of(a), bb = body_of(b);
        if (c2d_collide(&ba, &bb, model_.ball.restitution) != C2D_OK) return false;
        a.vx = ba.vel.x, a.vy = ba.vel.y;
        b.vx = bb.vel.x, b.vy = bb.vel.y;
        a.motion = motion_of(a);
        b.motion = motion_of(b);
        start_track(e.a, a, e.t);
        start_track(e.b, b, e.t);
    }
    ++stats.ball_ball_collisions;
    if (record_paths_) log.contacts.push_back(pair_key(e.a, e.b));
    const double ax = track_[static_cast<size_t>(e.a)].start.vx, ay = track_[static_cast<size_t>(e.a)].start.vy;
    const double impulse = kBallMass * std::fabs((ax - vax) * nx + (ay - vay) * ny);
    // one record for each ball, the lower-numbered first
    const bool a_first = balls_[static_cast<size_t>(e.a)].number <= balls_[static_cast<size_t>(e.b)].number;
    log_event(log, e.t, EventKind::BallBall, a_first ? e.a : e.b, a_first ? e.b : e.a, -1, impulse);
    log_event(log, e.t, EventKind::BallBall, a_first ? e.b : e.a, a_first ? e.a : e.b, -1, impulse);
    return true;
}

// A cushion face or a nose: returns whether the ball's motion changed.
bool ExactEngine::resolve_fixed(const Pending &e, Stats &stats, FrameLog &log) {
    Ball a = at(e.a, e.t);
    double nx, ny;  // unit normal from the ball towards what it hits
    EventKind kind;
    int feature;
    if (e.kind == kWallProxy) {
        const Wall &w = walls_[static_cast<size_t>(e.b)];
        nx = -w.s.nx, ny = -w.s.ny, kind = w.kind, feature = w.feature;
    } else {
        const Nose &k = noses_[static_cast<size_t>(e.b)];
        const double d = std::hypot(k.x - a.x, k.y - a.y);
        nx = (k.x - a.x) / d, ny = (k.y - a.y) / d, kind = EventKind::Jaw, feature = k.feature;
    }
    const double vax = a.vx, vay = a.vy;
    const double cx = a.x + nx * kBallRadius, cy = a.y + ny * kBallRadius;  // the contact point
    switch (contact(a.vx * nx + a.vy * ny)) {
    case Contact::Absorbed: {
        const Ball a0 = a;
        a = absorbed(e.a, e.t);
        if (same_motion(a, a0)) return false;  // nothing to take: no contact
        break;
    }
    case Contact::Impact: {
        c2d_status status;
        if (model_.friction) {
            c2d_disk da = disk_of(a);
            if (e.kind == kWallProxy) {
                c2d_disk wall = static_disk(cx, cy, 0);
                status = c2d_collide_rough_normal(&da, &wall, c2d_vec2{nx, ny}, surface_of(model_.cushion));
            } else {
                const Nose &k = noses_[static_cast<size_t>(e.b)];
                c2d_disk nose = static_disk(k.x, k.y, k.r);
                status = c2d_collide_rough(&da, &nose, surface_of(model_.cushion));
            }
            a.vx = da.vel.x, a.vy = da.vel.y, a.wz = da.spin;
        } else {
            c2d_body ba = body_of(a);
            if (e.kind == kWallProxy) {
                c2d_body wall = static_body(cx, cy);
                status = c2d_collide_normal(&ba, &wall, c2d_vec2{nx, ny}, model_.cushion.restitution);
            } else {
                const Nose &k = noses_[static_cast<size_t>(e.b)];
                c2d_body nose = static_body(k.x, k.y);
                status = c2d_collide(&ba, &nose, model_.cushion.restitution);
            }
            a.vx = ba.vel.x, a.vy = ba.vel.y;
        }
        if (status != C2D_OK) return false;
    }
    }
    a.motion = motion_of(a);
    start_track(e.a, a, e.t);
    ++stats.cushion_collisions;
    log_event(log, e.t, kind, e.a, -1, feature, kBallMass * std::fabs((a.vx - vax) * nx + (a.vy - vay) * ny));
    return true;
}

void ExactEngine::pocket(const Pending &e, Stats &stats, FrameLog &log) {
    const Ball a = at(e.a, e.t);
    remove(e.a);
    balls_[static_cast<size_t>(e.a)].x = a.x;
    balls_[static_cast<size_t>(e.a)].y = a.y;
    if (balls_[static_cast<size_t>(e.a)].number == 0) ++stats.scratches;
    else ++stats.pocketed;
    log_event(log, e.t, EventKind::Pocket, e.a, -1, e.b, kBallMass * std::hypot(a.vx, a.vy));
}

void ExactEngine::transition(const Pending &e, FrameLog &log) {
    const Ball b = state_after_transition(track_[static_cast<size_t>(e.a)]);
    // named by the state entered: rolling, spinning in place, at rest
    EventKind kind = EventKind::Stop;
    if (b.motion == Motion::Rolling) kind = EventKind::SlideToRoll;
    else if (b.motion == Motion::Spinning) kind = EventKind::RollToSpin;
    start_track(e.a, b, e.t);
    log_event(log, e.t, kind, e.a, -1, -1, 0);
}

// Returns whether ball e.a (and e.b for a pair) has a new track.
bool ExactEngine::resolve(const Pending &e, Stats &stats, FrameLog &log) {
    switch (e.kind) {
    case kBallProxy: return resolve_balls(e, stats, log);
    case kWallProxy:
    case kNoseProxy: return resolve_fixed(e, stats, log);
    case kHoleProxy: pocket(e, stats, log); return false;
    default: transition(e, log); return true;
    }
}

// Processes the events up to t_limit; false if the budget ran out first.
bool ExactEngine::process(double t_limit, long budget, Stats &stats, FrameLog &log) {
    long processed = 0;
    Pending e;
    while (queue_.pop_until(t_limit, e)) {
        if (e.gen_a != gen_[static_cast<size_t>(e.a)]) continue;
        if (e.kind == kBallProxy && e.gen_b != gen_[static_cast<size_t>(e.b)]) continue;
        if (++processed > budget) return false;
        now_ = e.t;
        if (e.kind == kSweepExpires) {
            sweep(e.a);
            find_events(e.a);
            continue;
        }
        moved_.clear();
        if (!resolve(e, stats, log)) continue;
        if (record_paths_)
            for (int i : moved_) log_waypoint(log, i);
        for (size_t k = moved_.size(); k-- > 0;) find_events(moved_[k]);
    }
    return true;
}

// Where ball i's new track starts, for the checker.
void ExactEngine::log_waypoint(FrameLog &log, int i) const {
    const Track &tr = track_[static_cast<size_t>(i)];
    log.waypoints.push_back(Waypoint{i, tr.t0, tr.start.x, tr.start.y, tr.start.vx, tr.start.vy, tr.ax, tr.ay});
}

void ExactEngine::sample(double t) {
    for (size_t i = 0; i < balls_.size(); ++i)
        if (balls_[i].active) balls_[i] = at(static_cast<int>(i), t);
}

void ExactEngine::step(double dt, Stats &stats, FrameLog &log) {
    record_paths_ = true;
    find_events_of_changed();
    const double frame_start = now_, frame_end = now_ + dt;
    // accelerating balls curve: the checker needs their motion from the start
    for (size_t i = 0; i < balls_.size(); ++i) {
        const Track &tr = track_[i];
        if (tr.start.active && (tr.ax != 0 || tr.ay != 0)) {
            const Ball b = at(static_cast<int>(i), now_);
            log.waypoints.push_back(Waypoint{static_cast<int>(i), now_, b.x, b.y, b.vx, b.vy, tr.ax, tr.ay});
        }
    }
    // Every impact makes a pair separate or removes a ball, but chains of
    // simultaneous contacts (inelastic collapse) could go on for ever.
    const long budget = 10000 + 100L * static_cast<long>(balls_.size());
    const bool done = process(frame_end, budget, stats, log);
    now_ = frame_end;
    sample(now_);
    // waypoint times are relative to the frame for the checker
    for (Waypoint &w : log.waypoints) w.t -= frame_start;
    if (!done) {
        ++stats.event_cap_frames;
        restart();
    }
}

bool ExactEngine::settle(double max_seconds, Stats &stats, FrameLog &log) {
    record_paths_ = false;
    find_events_of_changed();
    const double end = now_ + max_seconds;
    const long budget = 200000 + 10000L * static_cast<long>(balls_.size());
    const bool done = process(end, budget, stats, log);
    const bool rest = done && queue_.empty();
    if (done && !rest) now_ = end;  // else: the last event's time
    sample(now_);
    record_paths_ = true;
    return rest;
}

}  // namespace

std::unique_ptr<Engine> make_exact_engine(const std::vector<Ball> &balls, const Table &table, const Model &model,
                                          bool cell_grid) {
    return std::unique_ptr<Engine>(new ExactEngine(balls, table, model, cell_grid));
}

}  // namespace demo
