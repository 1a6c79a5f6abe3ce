// box2d_engine.cpp - see box2d_engine.h.  Balls are dynamic circles
// without friction or rotation, cushions two-sided edges, pockets sensors
// that drop a ball once its centre is inside; lengths are scaled by
// kUnitsPerMetre on the way in and out.
#include "box2d_engine.h"

#include <box2d/box2d.h>

#include <algorithm>

namespace demo {

namespace {

class Box2dEngine : public Engine, public b2ContactListener {
public:
    Box2dEngine(const std::vector<Ball> &balls, const Table &table, Restitution restitution);
    void step(double dt, Stats &stats, FrameLog &log) override;
    void set_velocity(int i, double vx, double vy) override;
    void place_ball(int i, Point p) override;

    void BeginContact(b2Contact *contact) override;
    void PreSolve(b2Contact *contact, const b2Manifold *old) override;
    void PostSolve(b2Contact *contact, const b2ContactImpulse *impulse) override;

private:
    static int ball_index(b2Fixture *f);
    void add_body(int i);
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
    : Engine(balls), world_(b2Vec2(0, 0)), e_ball_(restitution.ball), e_cushion_(restitution.cushion) {
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
    for (size_t i = 0; i < balls_.size(); ++i) add_body(static_cast<int>(i));
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
    body->SetLinearVelocity(b2Vec2(static_cast<float>(vx * kUnitsPerMetre), static_cast<float>(vy * kUnitsPerMetre)));
}

void Box2dEngine::place_ball(int i, Point p) {
    Ball &b = balls_[static_cast<size_t>(i)];
    if (b.active) return;
    b = Ball{p.x, p.y, 0, 0, b.number, true};
    add_body(i);
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

std::unique_ptr<Engine> make_box2d_engine(const std::vector<Ball> &balls, const Table &table, Restitution restitution) {
    return std::unique_ptr<Engine>(new Box2dEngine(balls, table, restitution));
}

}  // namespace demo
