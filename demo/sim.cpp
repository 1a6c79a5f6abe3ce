// sim.cpp - the exact event-driven engine (collide2d), the
// Box2D-solver engine for comparison, and the independent frame checker.
#include "sim.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <queue>
#include <utility>

extern "C" {
#include "collide2d.h"
}

namespace demo {

namespace {

// Box2D is tuned for bodies of 0.1-10 units and moves a body at most
// b2_maxTranslation (2 units) per step: 8 units per metre makes a ball 0.46
// units and keeps 15 m/s under that limit at 60 frames/s.  A power of two, so
// converting to and from Box2D units is exact.
constexpr double kUnitsPerMetre = 8.0;

constexpr double kStopSpeed = 0.01;            // m/s

uint64_t pair_key(int i, int j) {
    if (i > j) std::swap(i, j);
    return (static_cast<uint64_t>(i) << 32) | static_cast<uint32_t>(j);
}

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

}  // namespace

// ------------------------------------------------------------------ engines

// Where a ball's straight motion bends inside a frame (an impact it took).
struct Waypoint {
    int ball;
    double t, x, y;
    bool operator<(const Waypoint &o) const { return ball != o.ball ? ball < o.ball : t < o.t; }
};

struct FrameLog {
    std::vector<uint64_t> contacts;    // pairs resolved this frame
    std::vector<Waypoint> waypoints;   // exact engine only: Box2D moves straight per step
};

class Engine {
public:
    virtual ~Engine() = default;
    virtual void step(double dt, Stats &stats, FrameLog &log) = 0;
    // Called after the caller changed balls_[i] (shot, rolling resistance, respot).
    virtual void velocities_changed() = 0;
    virtual void ball_placed(int i) = 0;
    std::vector<Ball> balls_;
};

namespace {

// --- exact engine: Box2D's dynamic tree for candidates, collide2d for the rest

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
// the two swept last.
class ExactEngine : public Engine {
public:
    ExactEngine(const std::vector<Ball> &balls, const Table &table, Restitution restitution);
    void step(double dt, Stats &stats, FrameLog &log) override;
    void velocities_changed() override;
    void ball_placed(int i) override;

    bool QueryCallback(int32 proxy);

private:
    void insert_statics();
    void advance(int i, double t);
    void sweep(int i);
    void find_events(int i, bool initial);
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
    : table_(table), e_ball_(restitution.ball), e_cushion_(restitution.cushion) {
    balls_ = balls;
    tb_.assign(balls.size(), 0.0);
    horizon_.assign(balls.size(), 0.0);
    gen_.assign(balls.size(), 0u);
    proxy_.assign(balls.size(), b2_nullNode);
    swept_.resize(balls.size());
    insert_statics();
    // Qualified: no virtual dispatch from a constructor.
    for (size_t i = 0; i < balls_.size(); ++i) ExactEngine::ball_placed(static_cast<int>(i));
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

void ExactEngine::ball_placed(int i) {
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

// Ball i must be at now_.  initial: every ball is being swept at once, so a
// pair of moving balls is left to its lower index.
void ExactEngine::find_events(int i, bool initial) {
    hits_.clear();
    tree_.Query(this, swept_[static_cast<size_t>(i)]);
    for (int32 proxy : hits_) {
        const uintptr_t t = reinterpret_cast<uintptr_t>(tree_.GetUserData(proxy));
        const int kind = static_cast<int>(t & 3u), index = static_cast<int>(t >> 2);
        switch (kind) {
        case kBallProxy: {
            if (index == i) break;
            const Ball &o = balls_[static_cast<size_t>(index)];
            if (initial && index < i && (o.vx != 0 || o.vy != 0)) break;
            event_with_ball(i, index);
            break;
        }
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

// Every ball's motion may have changed (shot, rolling resistance): forget all
// events and find them again.
void ExactEngine::restart() {
    queue_ = {};
    const int n = static_cast<int>(balls_.size());
    for (int i = 0; i < n; ++i) {
        if (!balls_[static_cast<size_t>(i)].active) continue;
        ++gen_[static_cast<size_t>(i)];
        sweep(i);
    }
    for (int i = 0; i < n; ++i) {
        const Ball &b = balls_[static_cast<size_t>(i)];
        if (b.active && (b.vx != 0 || b.vy != 0)) find_events(i, true);
    }
}

void ExactEngine::velocities_changed() { restart(); }

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
            find_events(e.a, false);
            continue;
        }
        if (!resolve(e, stats, log)) continue;
        motion_changed(e.a);
        if (e.kind == kBallProxy) {
            motion_changed(e.b);
            find_events(e.b, false);
        }
        find_events(e.a, false);
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

// --- Box2D's own solver, for comparison

class Box2dEngine : public Engine, public b2ContactListener {
public:
    Box2dEngine(const std::vector<Ball> &balls, const Table &table, Restitution restitution);
    void step(double dt, Stats &stats, FrameLog &log) override;
    void velocities_changed() override;
    void ball_placed(int i) override;

    void BeginContact(b2Contact *contact) override;
    void PreSolve(b2Contact *contact, const b2Manifold *old) override;
    void PostSolve(b2Contact *contact, const b2ContactImpulse *impulse) override;

private:
    static int ball_index(b2Fixture *f);
    void drop_pocketed(Stats &stats);

    b2World world_;
    std::vector<b2Body *> bodies_;
    double e_ball_, e_cushion_;
    Stats *stats_ = nullptr;
    FrameLog *log_ = nullptr;
};

// user data: ball index + 1 on ball fixtures, 0 cushion, -1 - pocket on pockets
int Box2dEngine::ball_index(b2Fixture *f) {
    return static_cast<int>(f->GetUserData().pointer) - 1;
}

Box2dEngine::Box2dEngine(const std::vector<Ball> &balls, const Table &table, Restitution restitution)
    : world_(b2Vec2(0, 0)), e_ball_(restitution.ball), e_cushion_(restitution.cushion) {
    balls_ = balls;
    world_.SetContactListener(this);
    b2BodyDef ground_def;
    b2Body *ground = world_.CreateBody(&ground_def);
    for (const Segment &s : table.cushions) {
        // the edge's skin (b2_polygonRadius) is the contact surface: shift the
        // edge out by it so the face sits on the cushion line
        const double skin = b2_polygonRadius / kUnitsPerMetre;
        b2EdgeShape edge;
        edge.SetTwoSided(b2Vec2(static_cast<float>((s.ax - s.nx * skin) * kUnitsPerMetre), static_cast<float>((s.ay - s.ny * skin) * kUnitsPerMetre)),
                         b2Vec2(static_cast<float>((s.bx - s.nx * skin) * kUnitsPerMetre), static_cast<float>((s.by - s.ny * skin) * kUnitsPerMetre)));
        b2FixtureDef fd;
        fd.shape = &edge;
        fd.friction = 0;
        fd.restitution = static_cast<float>(e_cushion_);
        ground->CreateFixture(&fd);
    }
    for (size_t p = 0; p < table.pockets.size(); ++p) {
        b2CircleShape circle;
        circle.m_p.Set(static_cast<float>(table.pockets[p].x * kUnitsPerMetre), static_cast<float>(table.pockets[p].y * kUnitsPerMetre));
        circle.m_radius = static_cast<float>(table.pockets[p].capture_radius * kUnitsPerMetre);
        b2FixtureDef fd;
        fd.shape = &circle;
        fd.isSensor = true;
        fd.userData.pointer = static_cast<uintptr_t>(-1 - static_cast<intptr_t>(p));
        ground->CreateFixture(&fd);
    }
    bodies_.assign(balls_.size(), nullptr);
    // Qualified: no virtual dispatch from a constructor.
    for (size_t i = 0; i < balls_.size(); ++i) Box2dEngine::ball_placed(static_cast<int>(i));
}

void Box2dEngine::ball_placed(int i) {
    Ball &b = balls_[static_cast<size_t>(i)];
    if (!b.active || bodies_[static_cast<size_t>(i)]) return;
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(static_cast<float>(b.x * kUnitsPerMetre), static_cast<float>(b.y * kUnitsPerMetre));
    def.linearVelocity.Set(static_cast<float>(b.vx * kUnitsPerMetre), static_cast<float>(b.vy * kUnitsPerMetre));
    def.fixedRotation = true;
    b2Body *body = world_.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(kBallRadius * kUnitsPerMetre);
    b2FixtureDef fd;
    fd.shape = &circle;
    fd.density = 1;
    fd.friction = 0;
    fd.restitution = static_cast<float>(e_ball_);
    fd.userData.pointer = static_cast<uintptr_t>(i) + 1;
    body->CreateFixture(&fd);
    bodies_[static_cast<size_t>(i)] = body;
}

void Box2dEngine::velocities_changed() {
    for (size_t i = 0; i < balls_.size(); ++i)
        if (bodies_[i])
            bodies_[i]->SetLinearVelocity(b2Vec2(static_cast<float>(balls_[i].vx * kUnitsPerMetre),
                                                 static_cast<float>(balls_[i].vy * kUnitsPerMetre)));
}

void Box2dEngine::BeginContact(b2Contact *contact) {
    const int a = ball_index(contact->GetFixtureA()), b = ball_index(contact->GetFixtureB());
    if (a < -1 || b < -1) return;  // pocket sensor
    if (a >= 0 && b >= 0) {
        ++stats_->ball_ball_collisions;
        log_->contacts.push_back(pair_key(a, b));
    } else {
        ++stats_->cushion_collisions;
    }
}

// Restitution per pair type (Box2D would mix the two fixtures' values).
void Box2dEngine::PreSolve(b2Contact *contact, const b2Manifold *) {
    const int a = ball_index(contact->GetFixtureA()), b = ball_index(contact->GetFixtureB());
    contact->SetRestitution(static_cast<float>(a >= 0 && b >= 0 ? e_ball_ : e_cushion_));
}

void Box2dEngine::PostSolve(b2Contact *contact, const b2ContactImpulse *) {
    const int a = ball_index(contact->GetFixtureA()), b = ball_index(contact->GetFixtureB());
    if (a >= 0 && b >= 0) log_->contacts.push_back(pair_key(a, b));
}

void Box2dEngine::drop_pocketed(Stats &stats) {
    std::vector<int> drop;
    for (b2Contact *c = world_.GetContactList(); c; c = c->GetNext()) {
        const int a = ball_index(c->GetFixtureA()), b = ball_index(c->GetFixtureB());
        const int pocket_code = std::min(a, b), ball = std::max(a, b);
        if (pocket_code >= -1 || ball < 0) continue;
        const b2Body *body = bodies_[static_cast<size_t>(ball)];
        const b2CircleShape *pocket = static_cast<const b2CircleShape *>(
            (a < -1 ? c->GetFixtureA() : c->GetFixtureB())->GetShape());
        if (b2DistanceSquared(body->GetPosition(), pocket->m_p) <= pocket->m_radius * pocket->m_radius)
            drop.push_back(ball);
    }
    std::sort(drop.begin(), drop.end());
    drop.erase(std::unique(drop.begin(), drop.end()), drop.end());
    for (int i : drop) {
        world_.DestroyBody(bodies_[static_cast<size_t>(i)]);
        bodies_[static_cast<size_t>(i)] = nullptr;
        balls_[static_cast<size_t>(i)].active = false;
        ++stats.pocketed;
    }
}

void Box2dEngine::step(double dt, Stats &stats, FrameLog &log) {
    stats_ = &stats;
    log_ = &log;
    world_.Step(static_cast<float>(dt), 8, 3);
    for (size_t i = 0; i < balls_.size(); ++i) {
        if (!bodies_[i]) continue;
        const b2Vec2 p = bodies_[i]->GetPosition(), v = bodies_[i]->GetLinearVelocity();
        balls_[i].x = p.x / kUnitsPerMetre;
        balls_[i].y = p.y / kUnitsPerMetre;
        balls_[i].vx = v.x / kUnitsPerMetre;
        balls_[i].vy = v.y / kUnitsPerMetre;
    }
    drop_pocketed(stats);
}

}  // namespace

// ------------------------------------------------------------------ checker

// Independent of the engines: each frame, every pair whose motion during the
// frame brings them into contact (c2d_time_of_impact on each straight piece
// of the two paths) and out the other side, without a contact the engine
// resolved, is a tunnelled pair.  Overlaps are measured at the frame's end.
struct Simulation::Checker {
    struct Box { double x0, y0, x1, y1; };
    std::vector<Box> box;              // each live ball's path this frame, plus its radius
    std::vector<char> live;
    std::vector<Waypoint> points;      // this frame's waypoints, sorted by ball then time
    std::vector<size_t> first;         // points[first[i] .. first[i+1]) belong to ball i
    std::vector<size_t> cell_of, cell_start, by_cell;
};

namespace {

// A ball's path over the frame: straight pieces between its waypoints.
struct Path {
    const Ball *start, *end;
    const Waypoint *bends, *bends_end;
    double dt;
    void at(double t, double &x, double &y) const {
        double t0 = 0, x0 = start->x, y0 = start->y;
        const Waypoint *w = bends;
        while (w != bends_end && w->t <= t) {
            t0 = w->t, x0 = w->x, y0 = w->y;
            ++w;
        }
        const double t1 = w != bends_end ? w->t : dt;
        const double x1 = w != bends_end ? w->x : end->x, y1 = w != bends_end ? w->y : end->y;
        const double f = t1 > t0 ? (t - t0) / (t1 - t0) : 0.0;
        x = x0 + (x1 - x0) * f;
        y = y0 + (y1 - y0) * f;
    }
};

void piece_body(const Path &p, double t0, double t1, c2d_body &b) {
    double x1, y1;
    p.at(t0, b.pos.x, b.pos.y);
    // the position just before t1 (a bend at t1 starts the next piece)
    const Waypoint *w = p.bends;
    while (w != p.bends_end && w->t < t1) ++w;
    if (w != p.bends_end && w->t == t1) x1 = w->x, y1 = w->y;
    else p.at(t1, x1, y1);
    b.vel.x = (x1 - b.pos.x) / (t1 - t0);
    b.vel.y = (y1 - b.pos.y) / (t1 - t0);
    b.mass = kBallMass;
}

bool entered(const Path &a, const Path &b) {
    std::vector<double> cuts = {0.0, a.dt};
    for (const Waypoint *w = a.bends; w != a.bends_end; ++w) cuts.push_back(w->t);
    for (const Waypoint *w = b.bends; w != b.bends_end; ++w) cuts.push_back(w->t);
    std::sort(cuts.begin(), cuts.end());
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double t0 = cuts[k], t1 = cuts[k + 1];
        if (t1 <= t0) continue;
        c2d_body pa, pb;
        piece_body(a, t0, t1, pa);
        piece_body(b, t0, t1, pb);
        double t;
        // Positions carry rounding, and a piece can be 1e-17 s long, so its
        // velocity is noise: count only a real entry, deeper than 1e-9 of a
        // diameter (a pair that crosses goes a whole diameter deep).
        if (c2d_time_of_impact(&pa, &pb, kBallDiameter * (1 - 1e-9), &t) == C2D_OK && t < t1 - t0) return true;
    }
    return false;
}

double cushion_overlap(const Ball &b, const Table &table) {
    double worst = 0;
    for (const Segment &s : table.cushions) {
        const double ex = s.bx - s.ax, ey = s.by - s.ay;
        const double along = (b.x - s.ax) * ex + (b.y - s.ay) * ey;
        if (along < 0 || along > ex * ex + ey * ey) continue;
        const double depth = kBallRadius - ((b.x - s.ax) * s.nx + (b.y - s.ay) * s.ny);
        worst = std::max(worst, depth / kBallDiameter);
    }
    return worst;
}

}  // namespace

void Simulation::index_waypoints(size_t n) {
    Checker &c = *checker_;
    c.points = frame_log_->waypoints;
    std::stable_sort(c.points.begin(), c.points.end());
    c.first.assign(n + 1, 0);
    for (const Waypoint &w : c.points) ++c.first[static_cast<size_t>(w.ball) + 1];
    for (size_t i = 0; i < n; ++i) c.first[i + 1] += c.first[i];
}

// Candidate pairs for the checker come from a uniform grid, not from Box2D,
// so the check shares nothing with the engines.  Cells are at least as wide
// as the largest path box: boxes that overlap sit in neighbouring cells.
template <typename Visit>
void Simulation::for_each_close_pair(Visit visit) {
    Checker &c = *checker_;
    const size_t n = c.box.size();
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY, cell = kBallDiameter;
    for (size_t i = 0; i < n; ++i) {
        if (!c.live[i]) continue;
        const Checker::Box &b = c.box[i];
        x0 = std::min(x0, b.x0), y0 = std::min(y0, b.y0), x1 = std::max(x1, b.x1), y1 = std::max(y1, b.y1);
        cell = std::max(cell, std::max(b.x1 - b.x0, b.y1 - b.y0));
    }
    if (!(x0 <= x1)) return;
    cell = std::max(cell, std::max(x1 - x0, y1 - y0) / 2048);  // bounded grid, whatever the spread
    const size_t nx = static_cast<size_t>((x1 - x0) / cell) + 1, ny = static_cast<size_t>((y1 - y0) / cell) + 1;
    c.cell_of.assign(n, 0);
    c.cell_start.assign(nx * ny + 1, 0);
    auto cell_x = [&](const Checker::Box &b) { return std::min(nx - 1, static_cast<size_t>((0.5 * (b.x0 + b.x1) - x0) / cell)); };
    auto cell_y = [&](const Checker::Box &b) { return std::min(ny - 1, static_cast<size_t>((0.5 * (b.y0 + b.y1) - y0) / cell)); };
    for (size_t i = 0; i < n; ++i) {
        if (!c.live[i]) continue;
        c.cell_of[i] = cell_y(c.box[i]) * nx + cell_x(c.box[i]);
        ++c.cell_start[c.cell_of[i] + 1];
    }
    for (size_t k = 0; k < nx * ny; ++k) c.cell_start[k + 1] += c.cell_start[k];
    c.by_cell.assign(c.cell_start[nx * ny], 0);
    std::vector<size_t> fill(c.cell_start.begin(), c.cell_start.end() - 1);
    for (size_t i = 0; i < n; ++i)
        if (c.live[i]) c.by_cell[fill[c.cell_of[i]]++] = i;
    for (size_t i = 0; i < n; ++i) {
        if (!c.live[i]) continue;
        const Checker::Box &bi = c.box[i];
        const size_t cx = c.cell_of[i] % nx, cy = c.cell_of[i] / nx;
        for (size_t gy = cy ? cy - 1 : 0; gy <= std::min(ny - 1, cy + 1); ++gy)
            for (size_t gx = cx ? cx - 1 : 0; gx <= std::min(nx - 1, cx + 1); ++gx)
                for (size_t k = c.cell_start[gy * nx + gx]; k < c.cell_start[gy * nx + gx + 1]; ++k) {
                    const size_t j = c.by_cell[k];
                    const Checker::Box &bj = c.box[j];
                    if (j > i && bi.x0 <= bj.x1 && bj.x0 <= bi.x1 && bi.y0 <= bj.y1 && bj.y0 <= bi.y1) visit(i, j);
                }
    }
}

void Simulation::check_frame(const std::vector<Ball> &before, double dt) {
    const std::vector<Ball> &after = engine_->balls_;
    Checker &c = *checker_;
    const size_t n = after.size();
    index_waypoints(n);
    c.box.resize(n);
    c.live.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        if (!before[i].active || !after[i].active) continue;
        c.live[i] = 1;
        Checker::Box &b = c.box[i];
        b = {std::min(before[i].x, after[i].x), std::min(before[i].y, after[i].y), std::max(before[i].x, after[i].x),
             std::max(before[i].y, after[i].y)};
        for (size_t k = c.first[i]; k < c.first[i + 1]; ++k) {
            b.x0 = std::min(b.x0, c.points[k].x), b.y0 = std::min(b.y0, c.points[k].y);
            b.x1 = std::max(b.x1, c.points[k].x), b.y1 = std::max(b.y1, c.points[k].y);
        }
        b.x0 -= kBallRadius, b.y0 -= kBallRadius, b.x1 += kBallRadius, b.y1 += kBallRadius;
        stats_.max_overlap = std::max(stats_.max_overlap, cushion_overlap(after[i], table_));
    }
    std::vector<uint64_t> &resolved = frame_log_->contacts;
    std::sort(resolved.begin(), resolved.end());
    auto path = [&](size_t i) {
        return Path{&before[i], &after[i], c.points.data() + c.first[i], c.points.data() + c.first[i + 1], dt};
    };
    for_each_close_pair([&](size_t i, size_t j) {
        const double gap = std::hypot(after[j].x - after[i].x, after[j].y - after[i].y);
        stats_.max_overlap = std::max(stats_.max_overlap, (kBallDiameter - gap) / kBallDiameter);
        // crossed: came into contact during the frame and is out the other side
        if (gap > kBallDiameter && entered(path(i), path(j)) &&
            !std::binary_search(resolved.begin(), resolved.end(), pair_key(static_cast<int>(i), static_cast<int>(j))))
            ++stats_.tunnelled;
    });
}

// ---------------------------------------------------------------- simulation

Simulation::Simulation(const SimConfig &config) : config_(config), frame_log_(new FrameLog), checker_(new Checker) {
    Layout start = set_up(config.scene, config.gas_balls, config.seed);
    table_ = std::move(start.table);
    balls_initial_ = std::move(start.balls);
    if (config.response == Response::Box2d)
        engine_.reset(new Box2dEngine(balls_initial_, table_, config.losses.restitution));
    else
        engine_.reset(new ExactEngine(balls_initial_, table_, config.losses.restitution));
    escaped_flag_.assign(balls_initial_.size(), 0);
}

Simulation::~Simulation() = default;

const std::vector<Ball> &Simulation::balls() const { return engine_->balls_; }

bool Simulation::cue_on_table() const {
    return config_.scene != Scene::Gas && engine_->balls_[0].active;
}

void Simulation::shoot(const Shot &shot) {
    if (!cue_on_table()) return;
    const double a = shot.angle_deg * (M_PI / 180.0);
    engine_->balls_[0].vx = shot.speed * std::cos(a);
    engine_->balls_[0].vy = shot.speed * std::sin(a);
    engine_->velocities_changed();
}

bool Simulation::at_rest() const {
    for (const Ball &b : engine_->balls_)
        if (b.active && (b.vx != 0 || b.vy != 0)) return false;
    return true;
}

int Simulation::object_balls_left() const {
    int left = 0;
    for (const Ball &b : engine_->balls_) left += b.active && b.number != 0;
    return left;
}

void Simulation::respot_cue() {
    Ball &cue = engine_->balls_[0];
    if (cue.active || config_.scene == Scene::Gas) return;
    const Point spot = free_head_spot(table_, engine_->balls_);
    cue = Ball{spot.x, spot.y, 0, 0, 0, true};
    engine_->ball_placed(0);
}

double Simulation::energy() const {
    double e = 0;
    for (const Ball &b : engine_->balls_)
        if (b.active) e += 0.5 * kBallMass * (b.vx * b.vx + b.vy * b.vy);
    return e;
}

void Simulation::momentum(double out[2]) const {
    out[0] = out[1] = 0;
    for (const Ball &b : engine_->balls_)
        if (b.active) {
            out[0] += kBallMass * b.vx;
            out[1] += kBallMass * b.vy;
        }
}

void Simulation::count_escaped() {
    const std::vector<Ball> &all = engine_->balls_;
    for (size_t i = 0; i < all.size(); ++i) {
        const Ball &b = all[i];
        const bool outside = b.x < 0 || b.x > table_.length || b.y < 0 || b.y > table_.width;
        if (b.active && outside && !escaped_flag_[i]) {
            escaped_flag_[i] = 1;
            ++stats_.escaped;
        }
    }
}

void Simulation::step() {
    const std::vector<Ball> before = engine_->balls_;
    frame_log_->contacts.clear();
    frame_log_->waypoints.clear();
    engine_->step(kFrameDt, stats_, *frame_log_);
    check_frame(before, kFrameDt);
    count_escaped();
    if (config_.losses.rolling_deceleration > 0) {
        // rolling resistance changes velocities only between frames, so the
        // motion inside a frame stays straight and its impacts exact
        for (Ball &b : engine_->balls_) {
            const double speed = std::hypot(b.vx, b.vy);
            if (speed == 0) continue;
            const double slower = speed - config_.losses.rolling_deceleration * kFrameDt;
            const double scale = slower < kStopSpeed ? 0.0 : slower / speed;
            b.vx *= scale;
            b.vy *= scale;
        }
        engine_->velocities_changed();
    }
    ++stats_.steps;
    stats_.sim_seconds = static_cast<double>(stats_.steps) * kFrameDt;
}

}  // namespace demo
