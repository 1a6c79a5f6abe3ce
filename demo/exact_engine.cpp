// exact_engine.cpp - see exact_engine.h.  Balls move straight between
// impacts, so impact times are exact up to rounding: two balls meet at the
// earliest t >= 0 with |dp + dv t| = 2r while approaching
// (c2d_time_of_impact); a cushion at gap g = (p - a).n - r, approached at
// speed -v.n > 0, is hit at t = g / (-v.n) if the contact lies on its face;
// cushion ends (jaws) and pocket centres are fixed points, at r and at the
// capture radius.  Impacts are resolved in time order (c2d_collide, or
// c2d_collide_normal with the cushion's normal); a pocket removes the ball.
#include "exact_engine.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <queue>

extern "C" {
#include "collide2d.h"
}

namespace demo {

namespace {

b2AABB aabb_of_disk_path(double x0, double y0, double x1, double y1, double radius) {
    b2AABB box;
    box.lowerBound.Set(static_cast<float>((std::min(x0, x1) - radius) * kUnitsPerMetre),
                       static_cast<float>((std::min(y0, y1) - radius) * kUnitsPerMetre));
    box.upperBound.Set(static_cast<float>((std::max(x0, x1) + radius) * kUnitsPerMetre),
                       static_cast<float>((std::max(y0, y1) + radius) * kUnitsPerMetre));
    // float rounding of the bounds must never shrink the box
    const float pad = 1e-4f;
    box.lowerBound -= b2Vec2(pad, pad);
    box.upperBound += b2Vec2(pad, pad);
    return box;
}

c2d_body body_of(const Ball &b) { return c2d_body{{b.x, b.y}, {b.vx, b.vy}, kBallMass}; }
c2d_body static_body(double x, double y) { return c2d_body{{x, y}, {0, 0}, INFINITY}; }

enum ProxyKind { kBallProxy = 0, kCushionProxy = 1, kJawProxy = 2, kPocketProxy = 3 };
constexpr int kSweepExpires = 4;  // event kind: a ball's swept box runs out

struct Event {
    double t;
    int a, kind, b;
    unsigned gen_a, gen_b;
    bool operator>(const Event &o) const {
        if (t != o.t) return t > o.t;
        if (a != o.a) return a > o.a;
        if (kind != o.kind) return kind > o.kind;
        return b > o.b;
    }
};

// Event-driven: the queue of impacts persists across frames.  Each moving
// ball's proxy in Box2D's dynamic tree covers its straight path over a
// horizon of a few diameters; a ball re-queries the tree when its motion
// changes or its horizon runs out, so a pair is always found by whichever of
// the two swept last.  An event carries the generations of its balls, and a
// ball's generation is bumped whenever its motion changes: an event a later
// change made stale is skipped when it comes up, never searched for.
class ExactEngine : public Engine {
public:
    ExactEngine(const std::vector<Ball> &balls, const Table &table, Restitution restitution);
    void step(double dt, Stats &stats, FrameLog &log) override;
    void set_velocity(int i, double vx, double vy) override;
    void place_ball(int i, Point p) override;

    bool QueryCallback(int32 proxy);

private:
    void insert_statics();
    void insert_ball(int i);
    bool moving(int i) const;
    void advance(int i, double t);
    void sweep(int i);
    void mark_changed(int i);
    void find_events_of_changed();
    bool leaves_pair_to(int i, int j) const;
    void find_events(int i);
    void event_with_ball(int i, int j);
    void event_with_cushion(int i, int c);
    void event_with_point(int i, double px, double py, double radius, int kind, int index);
    void push(double t, int i, int kind, int b);
    bool resolve(const Event &e, Stats &stats, FrameLog &log);
    void motion_changed(int i);
    void remove(int i);
    void restart();

    const Table table_;
    double e_ball_, e_cushion_;
    std::vector<double> jaw_x_, jaw_y_;
    std::vector<double> tb_;         // time of the stored position
    std::vector<double> horizon_;    // end of the ball's swept box
    std::vector<unsigned> gen_;      // bumped whenever a ball's motion changes
    std::vector<int> changed_;       // balls changed from outside since the last step
    std::vector<char> is_changed_;
    std::vector<int32> proxy_;
    std::vector<b2AABB> swept_;
    b2DynamicTree tree_;
    std::priority_queue<Event, std::vector<Event>, std::greater<Event>> queue_;
    double now_ = 0;
    std::vector<int32> hits_;
};

// b2DynamicTree 2.4.1 carries a void * per proxy; ours is a small integer
// that round-trips exactly and is never dereferenced.
void *tag(int kind, int index) {
    return reinterpret_cast<void *>(static_cast<uintptr_t>(index) * 4 + static_cast<uintptr_t>(kind)); // NOLINT(performance-no-int-to-ptr)
}

ExactEngine::ExactEngine(const std::vector<Ball> &balls, const Table &table, Restitution restitution)
    : Engine(balls), table_(table), e_ball_(restitution.ball), e_cushion_(restitution.cushion) {
    tb_.assign(balls.size(), 0.0);
    horizon_.assign(balls.size(), 0.0);
    gen_.assign(balls.size(), 0u);
    proxy_.assign(balls.size(), b2_nullNode);
    swept_.resize(balls.size());
    is_changed_.assign(balls.size(), 0);
    insert_statics();
    for (size_t i = 0; i < balls_.size(); ++i) insert_ball(static_cast<int>(i));
    restart();
}

void ExactEngine::insert_statics() {
    for (size_t c = 0; c < table_.cushions.size(); ++c) {
        const Segment &s = table_.cushions[c];
        tree_.CreateProxy(aabb_of_disk_path(s.ax, s.ay, s.bx, s.by, 0), tag(kCushionProxy, static_cast<int>(c)));
        // the cushion's ends (pocket jaws) are hit like fixed points
        if (!table_.pockets.empty()) {
            for (int end = 0; end < 2; ++end) {
                jaw_x_.push_back(end ? s.bx : s.ax);
                jaw_y_.push_back(end ? s.by : s.ay);
                const int j = static_cast<int>(jaw_x_.size()) - 1;
                tree_.CreateProxy(aabb_of_disk_path(jaw_x_[j], jaw_y_[j], jaw_x_[j], jaw_y_[j], 0), tag(kJawProxy, j));
            }
        }
    }
    for (size_t p = 0; p < table_.pockets.size(); ++p) {
        const Pocket &k = table_.pockets[p];
        tree_.CreateProxy(aabb_of_disk_path(k.x, k.y, k.x, k.y, k.capture_radius), tag(kPocketProxy, static_cast<int>(p)));
    }
}

void ExactEngine::insert_ball(int i) {
    const Ball &b = balls_[static_cast<size_t>(i)];
    if (proxy_[static_cast<size_t>(i)] != b2_nullNode || !b.active) return;
    tb_[static_cast<size_t>(i)] = now_;
    horizon_[static_cast<size_t>(i)] = INFINITY;
    swept_[static_cast<size_t>(i)] = aabb_of_disk_path(b.x, b.y, b.x, b.y, kBallRadius);
    proxy_[static_cast<size_t>(i)] = tree_.CreateProxy(swept_[static_cast<size_t>(i)], tag(kBallProxy, i));
}

void ExactEngine::advance(int i, double t) {
    const double h = t - tb_[static_cast<size_t>(i)];
    if (h != 0) {
        Ball &b = balls_[static_cast<size_t>(i)];
        b.x += b.vx * h;
        b.y += b.vy * h;
    }
    tb_[static_cast<size_t>(i)] = t;
}

// The box spans the straight path for a few diameters (at least a frame), so
// fast balls re-query often and slow ones rarely.
void ExactEngine::sweep(int i) {
    advance(i, now_);
    const Ball &b = balls_[static_cast<size_t>(i)];
    const double speed = std::hypot(b.vx, b.vy);
    const double h = speed > 0 ? std::min(1.0, std::max(kFrameDt, 2 * kBallDiameter / speed)) : INFINITY;
    const double reach = speed > 0 ? h : 0.0;
    swept_[static_cast<size_t>(i)] = aabb_of_disk_path(b.x, b.y, b.x + b.vx * reach, b.y + b.vy * reach, kBallRadius);
    horizon_[static_cast<size_t>(i)] = now_ + h;
    // no displacement hint: the box already spans the motion, and Box2D would
    // stretch it by four times the hint, making every query slower
    tree_.MoveProxy(proxy_[static_cast<size_t>(i)], swept_[static_cast<size_t>(i)], b2Vec2(0, 0));
    if (speed > 0) queue_.push(Event{now_ + h, i, kSweepExpires, -1, gen_[static_cast<size_t>(i)], 0u});
}

bool ExactEngine::QueryCallback(int32 proxy) {
    hits_.push_back(proxy);
    return true;
}

void ExactEngine::push(double t, int i, int kind, int b) {
    if (t > horizon_[static_cast<size_t>(i)]) return;  // re-found when the box is renewed
    const unsigned gb = kind == kBallProxy ? gen_[static_cast<size_t>(b)] : 0u;
    queue_.push(Event{t, i, kind, b, gen_[static_cast<size_t>(i)], gb});
}

void ExactEngine::event_with_ball(int i, int j) {
    const Ball &bj = balls_[static_cast<size_t>(j)];
    if (!bj.active) return;
    c2d_body a = body_of(balls_[static_cast<size_t>(i)]);
    c2d_body b = body_of(bj);
    const double h = now_ - tb_[static_cast<size_t>(j)];
    b.pos.x += bj.vx * h;
    b.pos.y += bj.vy * h;
    double t;
    if (c2d_time_of_impact(&a, &b, kBallDiameter, &t) == C2D_OK) push(now_ + t, i, kBallProxy, j);
}

void ExactEngine::event_with_cushion(int i, int c) {
    const Segment &s = table_.cushions[static_cast<size_t>(c)];
    const Ball &b = balls_[static_cast<size_t>(i)];
    const double approach = b.vx * s.nx + b.vy * s.ny;
    if (approach >= 0) return;
    const double gap = (b.x - s.ax) * s.nx + (b.y - s.ay) * s.ny - kBallRadius;
    const double t = gap > 0 ? gap / -approach : 0.0;
    const double ex = s.bx - s.ax, ey = s.by - s.ay;
    const double along = (b.x + b.vx * t - s.ax) * ex + (b.y + b.vy * t - s.ay) * ey;
    if (along < 0 || along > ex * ex + ey * ey) return;  // beyond the face: the jaw point takes it
    push(now_ + t, i, kCushionProxy, c);
}

void ExactEngine::event_with_point(int i, double px, double py, double radius, int kind, int index) {
    c2d_body a = body_of(balls_[static_cast<size_t>(i)]);
    c2d_body p = static_body(px, py);
    double t;
    if (c2d_time_of_impact(&a, &p, radius, &t) == C2D_OK) push(now_ + t, i, kind, index);
}

// Ball i must be at now_.
void ExactEngine::find_events(int i) {
    hits_.clear();
    tree_.Query(this, swept_[static_cast<size_t>(i)]);
    for (int32 proxy : hits_) {
        const uintptr_t t = reinterpret_cast<uintptr_t>(tree_.GetUserData(proxy));
        const int kind = static_cast<int>(t & 3u), index = static_cast<int>(t >> 2);
        switch (kind) {
        case kBallProxy:
            if (index != i && !leaves_pair_to(i, index)) event_with_ball(i, index);
            break;
        case kCushionProxy: event_with_cushion(i, index); break;
        case kJawProxy:
            event_with_point(i, jaw_x_[static_cast<size_t>(index)], jaw_y_[static_cast<size_t>(index)], kBallRadius, kind, index);
            break;
        default: {
            const Pocket &k = table_.pockets[static_cast<size_t>(index)];
            event_with_point(i, k.x, k.y, k.capture_radius, kind, index);
        }
        }
    }
}

void ExactEngine::remove(int i) {
    balls_[static_cast<size_t>(i)].active = false;
    tree_.DestroyProxy(proxy_[static_cast<size_t>(i)]);
    proxy_[static_cast<size_t>(i)] = b2_nullNode;
    ++gen_[static_cast<size_t>(i)];
}

// Forgets every event and finds them all again: at the start, and after a
// frame whose event budget ran out.
void ExactEngine::restart() {
    queue_ = {};
    for (size_t i = 0; i < balls_.size(); ++i) mark_changed(static_cast<int>(i));
    find_events_of_changed();
}

void ExactEngine::set_velocity(int i, double vx, double vy) {
    Ball &b = balls_[static_cast<size_t>(i)];
    if (!b.active) return;
    advance(i, now_);
    b.vx = vx;
    b.vy = vy;
    mark_changed(i);
}

void ExactEngine::place_ball(int i, Point p) {
    Ball &b = balls_[static_cast<size_t>(i)];
    if (b.active) return;
    b = Ball{p.x, p.y, 0, 0, b.number, true};
    insert_ball(i);
    mark_changed(i);
}

// Changes from outside come between frames, several at once (rolling
// resistance slows every moving ball): they are collected, and their events
// found when the next frame starts, all balls swept first.
void ExactEngine::mark_changed(int i) {
    if (!balls_[static_cast<size_t>(i)].active || is_changed_[static_cast<size_t>(i)]) return;
    is_changed_[static_cast<size_t>(i)] = 1;
    changed_.push_back(i);
}

void ExactEngine::find_events_of_changed() {
    std::sort(changed_.begin(), changed_.end());
    for (int i : changed_) {
        ++gen_[static_cast<size_t>(i)];
        sweep(i);
    }
    for (int i : changed_) find_events(i);
    for (int i : changed_) is_changed_[static_cast<size_t>(i)] = 0;
    changed_.clear();
}

// Of a pair changed together, one ball finds the pair's event, so it is not
// queued twice (the time seen from either ball can differ in the last bit):
// the moving one, or of two moving ones the lower index.  Two balls at rest
// never meet.
bool ExactEngine::leaves_pair_to(int i, int j) const {
    return is_changed_[static_cast<size_t>(j)] && moving(j) && (!moving(i) || j < i);
}

bool ExactEngine::moving(int i) const {
    const Ball &b = balls_[static_cast<size_t>(i)];
    return b.vx != 0 || b.vy != 0;
}

void ExactEngine::motion_changed(int i) {
    ++gen_[static_cast<size_t>(i)];
    sweep(i);
}

// Returns whether the ball(s) changed motion (and need new events).
bool ExactEngine::resolve(const Event &e, Stats &stats, FrameLog &log) {
    Ball &a = balls_[static_cast<size_t>(e.a)];
    advance(e.a, e.t);
    log.waypoints.push_back(Waypoint{e.a, e.t, a.x, a.y});
    c2d_body ba = body_of(a);
    c2d_status status;
    if (e.kind == kBallProxy) {
        Ball &b = balls_[static_cast<size_t>(e.b)];
        advance(e.b, e.t);
        log.waypoints.push_back(Waypoint{e.b, e.t, b.x, b.y});
        c2d_body bb = body_of(b);
        status = c2d_collide(&ba, &bb, e_ball_);
        if (status != C2D_OK) return false;
        b.vx = bb.vel.x;
        b.vy = bb.vel.y;
        ++stats.ball_ball_collisions;
        log.contacts.push_back(pair_key(e.a, e.b));
    } else if (e.kind == kCushionProxy) {
        const Segment &s = table_.cushions[static_cast<size_t>(e.b)];
        c2d_body wall = static_body(a.x - s.nx * kBallRadius, a.y - s.ny * kBallRadius);
        status = c2d_collide_normal(&ba, &wall, c2d_vec2{-s.nx, -s.ny}, e_cushion_);
        if (status != C2D_OK) return false;
        ++stats.cushion_collisions;
    } else if (e.kind == kJawProxy) {
        c2d_body jaw = static_body(jaw_x_[static_cast<size_t>(e.b)], jaw_y_[static_cast<size_t>(e.b)]);
        status = c2d_collide(&ba, &jaw, e_cushion_);
        if (status != C2D_OK) return false;
        ++stats.cushion_collisions;
    } else {
        remove(e.a);
        ++stats.pocketed;
        return false;
    }
    a.vx = ba.vel.x;
    a.vy = ba.vel.y;
    return true;
}

void ExactEngine::step(double dt, Stats &stats, FrameLog &log) {
    find_events_of_changed();
    const double frame_start = now_, frame_end = now_ + dt;
    // Every impact makes a pair separate or removes a ball, but chains of
    // simultaneous contacts (inelastic collapse) could go on for ever.
    const long budget = 10000 + 100L * static_cast<long>(balls_.size());
    long processed = 0;
    bool exhausted = false;
    while (!queue_.empty() && queue_.top().t <= frame_end) {
        const Event e = queue_.top();
        queue_.pop();
        if (e.gen_a != gen_[static_cast<size_t>(e.a)]) continue;
        if (e.kind == kBallProxy && e.gen_b != gen_[static_cast<size_t>(e.b)]) continue;
        if (++processed > budget) {
            exhausted = true;
            break;
        }
        now_ = e.t;
        if (e.kind == kSweepExpires) {
            sweep(e.a);
            find_events(e.a);
            continue;
        }
        if (!resolve(e, stats, log)) continue;
        motion_changed(e.a);
        if (e.kind == kBallProxy) {
            motion_changed(e.b);
            find_events(e.b);
        }
        find_events(e.a);
    }
    now_ = frame_end;
    for (size_t i = 0; i < balls_.size(); ++i)
        if (balls_[i].active) advance(static_cast<int>(i), frame_end);
    // waypoint times are relative to the frame for the checker
    for (Waypoint &w : log.waypoints) w.t -= frame_start;
    if (exhausted) {
        ++stats.event_cap_frames;
        restart();
    }
}

}  // namespace

std::unique_ptr<Engine> make_exact_engine(const std::vector<Ball> &balls, const Table &table, Restitution restitution) {
    return std::unique_ptr<Engine>(new ExactEngine(balls, table, restitution));
}

}  // namespace demo
