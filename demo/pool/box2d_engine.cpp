/* SPDX-License-Identifier: MIT */
// box2d_engine.cpp - see box2d_engine.h.  Balls are dynamic circles
// without friction or rotation, cushions and jaw facings two-sided edges,
// jaw noses static circles, pockets sensors that drop a ball once its centre
// is inside the hole; lengths are scaled by kUnitsPerMetre on the way in and
// out.  Box2D's balls do not spin: of the cloth they get rolling resistance
// only, mu_r g taken off each moving ball's speed after each step (below
// 1 cm/s it stops), and restitution at impacts.
#include "pool/box2d_engine.h"

#include <box2d/box2d.h>

#include "pool/det_math.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace demo {

namespace {

class Box2dEngine : public Engine, public b2ContactListener {
public:
    Box2dEngine(const std::vector<Ball> &balls, const Table &table, const Model &model);
    void step(double dt, Stats &stats, FrameLog &log) override;
    bool settle(double max_seconds, Stats &stats, FrameLog &log) override;
    void set_motion(int i, const Ball &state) override;
    void place_ball(int i, Point p) override;
    double now() const override { return now_; }

    void BeginContact(b2Contact *contact) override;
    void PreSolve(b2Contact *contact, const b2Manifold *old) override;
    void PostSolve(b2Contact *contact, const b2ContactImpulse *impulse) override;

private:
    static int ball_index(b2Fixture *f);
    void add_edge(b2Body *ground, const Segment &s);
    void add_body(int i);
    void set_velocity(int i, double vx, double vy);
    void drop_pocketed(Stats &stats, FrameLog &log);
    void roll(double dt);
    void contact_event(b2Contact *contact, int a, int b);

    b2World world_;
    std::vector<b2Body *> bodies_;
    double e_ball_, e_cushion_, rolling_deceleration_;
    double now_ = 0;
    Stats *stats_ = nullptr;
    FrameLog *log_ = nullptr;
};

// Below it a ball stops rather than crawl; and a last step's slowing can
// never reverse a ball.
constexpr double kStopSpeed = 0.01;  // m/s

// user data: ball index + 1 on ball fixtures, 0 cushion, -1 - pocket on pockets
int Box2dEngine::ball_index(b2Fixture *f) {
    return static_cast<int>(f->GetUserData().pointer) - 1;
}

Box2dEngine::Box2dEngine(const std::vector<Ball> &balls, const Table &table, const Model &model)
    : Engine(balls), world_(b2Vec2(0, 0)), e_ball_(model.ball.restitution), e_cushion_(model.cushion.restitution),
      rolling_deceleration_(model.friction ? model.cloth.roll * model.cloth.gravity : 0.0) {
    world_.SetContactListener(this);
    b2BodyDef ground_def;
    b2Body *ground = world_.CreateBody(&ground_def);
    for (const Segment &s : table.cushions) add_edge(ground, s);
    for (size_t p = 0; p < table.pockets.size(); ++p) {
        const Pocket &k = table.pockets[p];
        for (const Jaw &j : k.jaws) {
            add_edge(ground, j.facing);
            b2CircleShape nose;
            nose.m_p.Set(static_cast<float>(j.nose_x * kUnitsPerMetre), static_cast<float>(j.nose_y * kUnitsPerMetre));
            nose.m_radius = static_cast<float>(j.nose_r * kUnitsPerMetre);
            b2FixtureDef fd;
            fd.shape = &nose;
            fd.friction = 0;
            fd.restitution = static_cast<float>(e_cushion_);
            ground->CreateFixture(&fd);
        }
        b2CircleShape circle;
        circle.m_p.Set(static_cast<float>(k.x * kUnitsPerMetre), static_cast<float>(k.y * kUnitsPerMetre));
        circle.m_radius = static_cast<float>(k.capture_radius * kUnitsPerMetre);
        b2FixtureDef fd;
        fd.shape = &circle;
        fd.isSensor = true;
        fd.userData.pointer = static_cast<uintptr_t>(-1 - static_cast<intptr_t>(p));
        ground->CreateFixture(&fd);
    }
    bodies_.assign(balls_.size(), nullptr);
    for (size_t i = 0; i < balls_.size(); ++i) {
        balls_[i].wx = balls_[i].wy = balls_[i].wz = 0;
        add_body(static_cast<int>(i));
    }
}

// The edge's skin (b2_polygonRadius) is the contact surface: the edge is
// shifted out by it so the face sits on the cushion line.
void Box2dEngine::add_edge(b2Body *ground, const Segment &s) {
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

void Box2dEngine::add_body(int i) {
    const Ball &b = balls_[static_cast<size_t>(i)];
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

void Box2dEngine::set_velocity(int i, double vx, double vy) {
    Ball &b = balls_[static_cast<size_t>(i)];
    b2Body *body = bodies_[static_cast<size_t>(i)];
    if (!b.active || !body) return;
    b.vx = vx;
    b.vy = vy;
    b.motion = vx != 0 || vy != 0 ? Motion::Sliding : Motion::Stationary;
    body->SetLinearVelocity(b2Vec2(static_cast<float>(vx * kUnitsPerMetre), static_cast<float>(vy * kUnitsPerMetre)));
}

void Box2dEngine::set_motion(int i, const Ball &state) { set_velocity(i, state.vx, state.vy); }

void Box2dEngine::place_ball(int i, Point p) {
    Ball &b = balls_[static_cast<size_t>(i)];
    if (b.active) return;
    b = Ball{p.x, p.y, 0, 0, b.number, true};
    add_body(i);
}

// An event where the contact starts; Box2D's impulses are in its own mass
// units, so the event's impulse is the ball's mass times the speed with
// which the two approach.
void Box2dEngine::contact_event(b2Contact *contact, int a, int b) {
    b2WorldManifold m;
    contact->GetWorldManifold(&m);
    const b2Body *ba = contact->GetFixtureA()->GetBody(), *bb = contact->GetFixtureB()->GetBody();
    const b2Vec2 dv = bb->GetLinearVelocity() - ba->GetLinearVelocity();
    const double approach = std::fabs(b2Dot(dv, m.normal)) / kUnitsPerMetre;
    const double x = m.points[0].x / kUnitsPerMetre, y = m.points[0].y / kUnitsPerMetre;
    auto record = [&](int ball, int other) {
        const Ball &s = balls_[static_cast<size_t>(ball)];
        log_->events.push_back(Event{now_, other >= 0 ? EventKind::BallBall : EventKind::Cushion, ball, other, -1, x,
                                     y, s.vx, s.vy, 0, 0, 0, kBallMass * approach});
    };
    if (a < 0 || b < 0) {
        record(a >= 0 ? a : b, -1);
    } else {  // one record for each ball, as the world engine
        const bool a_first = balls_[static_cast<size_t>(a)].number <= balls_[static_cast<size_t>(b)].number;
        record(a_first ? a : b, a_first ? b : a);
        record(a_first ? b : a, a_first ? a : b);
    }
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
    contact_event(contact, a, b);
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

void Box2dEngine::drop_pocketed(Stats &stats, FrameLog &log) {
    std::vector<std::pair<int, int>> drop;  // ball, pocket
    for (b2Contact *c = world_.GetContactList(); c; c = c->GetNext()) {
        const int a = ball_index(c->GetFixtureA()), b = ball_index(c->GetFixtureB());
        const int pocket_code = std::min(a, b), ball = std::max(a, b);
        if (pocket_code >= -1 || ball < 0) continue;
        const b2Body *body = bodies_[static_cast<size_t>(ball)];
        const b2CircleShape *pocket = static_cast<const b2CircleShape *>(
            (a < -1 ? c->GetFixtureA() : c->GetFixtureB())->GetShape());
        if (b2DistanceSquared(body->GetPosition(), pocket->m_p) <= pocket->m_radius * pocket->m_radius)
            drop.emplace_back(ball, -2 - pocket_code);
    }
    std::sort(drop.begin(), drop.end());
    drop.erase(std::unique(drop.begin(), drop.end(), [](const auto &x, const auto &y) { return x.first == y.first; }), drop.end());
    for (const auto &d : drop) {
        const size_t i = static_cast<size_t>(d.first);
        world_.DestroyBody(bodies_[i]);
        bodies_[i] = nullptr;
        Ball &b = balls_[i];
        log.events.push_back(Event{now_, EventKind::Pocket, d.first, -1, d.second, b.x, b.y, 0, 0, 0, 0, 0,
                                   kBallMass * det_hypot(b.vx, b.vy)});
        b.active = false;
        b.vx = b.vy = 0;
        b.motion = Motion::Pocketed;
        if (b.number == 0) ++stats.scratches;
        else ++stats.pocketed;
    }
}

// Rolling resistance changes velocities only between steps, so the motion
// inside a step stays straight and Box2D's own.
void Box2dEngine::roll(double dt) {
    const double slowing = rolling_deceleration_ * dt;
    for (size_t i = 0; i < balls_.size(); ++i) {
        const Ball &b = balls_[i];
        const double speed = det_hypot(b.vx, b.vy);
        if (!b.active || speed == 0) continue;
        const double slower = speed - slowing;
        const double scale = slower < kStopSpeed ? 0.0 : slower / speed;
        set_velocity(static_cast<int>(i), b.vx * scale, b.vy * scale);
    }
}

void Box2dEngine::step(double dt, Stats &stats, FrameLog &log) {
    stats_ = &stats;
    log_ = &log;
    world_.Step(static_cast<float>(dt), 8, 3);
    now_ += dt;
    for (size_t i = 0; i < balls_.size(); ++i) {
        if (!bodies_[i]) continue;
        const b2Vec2 p = bodies_[i]->GetPosition(), v = bodies_[i]->GetLinearVelocity();
        balls_[i].x = p.x / kUnitsPerMetre;
        balls_[i].y = p.y / kUnitsPerMetre;
        balls_[i].vx = v.x / kUnitsPerMetre;
        balls_[i].vy = v.y / kUnitsPerMetre;
    }
    drop_pocketed(stats, log);
    if (rolling_deceleration_ > 0) roll(dt);
}

bool Box2dEngine::settle(double max_seconds, Stats &stats, FrameLog &log) {
    const double end = now_ + max_seconds;
    for (;;) {
        bool moving = false;
        for (const Ball &b : balls_) moving = moving || (b.active && (b.vx != 0 || b.vy != 0));
        if (!moving) return true;
        if (now_ >= end) return false;
        step(kFrameDt, stats, log);
    }
}

}  // namespace

std::unique_ptr<Engine> make_box2d_engine(const std::vector<Ball> &balls, const Table &table, const Model &model) {
    return std::unique_ptr<Engine>(new Box2dEngine(balls, table, model));
}

}  // namespace demo
