/* SPDX-License-Identifier: MIT */
#include "box2d_contender.h"

#include <box2d/box2d.h>

#include <cmath>

namespace {

/* One step of 1/60 s: plain speeds stay far below b2_maxTranslation per
 * step, which would otherwise scale the velocity Box2D reports. */
constexpr float step_seconds = 1.0f / 60.0f;
constexpr int velocity_iterations = 8;
constexpr int position_iterations = 3;

struct Scene {
    b2World world{b2Vec2(0.0f, 0.0f)};
    b2Body *body[2] = {nullptr, nullptr};
    b2Fixture *fixture[2] = {nullptr, nullptr};
};

Scene *scene = nullptr;

b2Body *make_disk(b2World &world, b2Fixture **fixture)
{
    b2BodyDef bd;
    bd.type = b2_dynamicBody;
    bd.allowSleep = false;
    b2Body *body = world.CreateBody(&bd);
    b2CircleShape circle;
    circle.m_radius = 0.5f;
    b2FixtureDef fd;
    fd.shape = &circle;
    fd.density = 1.0f;
    fd.friction = 0.0f;
    fd.restitution = 1.0f;
    fd.restitutionThreshold = 0.0f;
    *fixture = body->CreateFixture(&fd);
    return body;
}

void place(b2Body *body, b2Fixture *fixture, const c2d_body *src, float radius)
{
    static_cast<b2CircleShape *>(fixture->GetShape())->m_radius = radius;
    body->SetTransform(b2Vec2(static_cast<float>(src->pos.x), static_cast<float>(src->pos.y)), 0.0f);
    body->SetLinearVelocity(b2Vec2(static_cast<float>(src->vel.x), static_cast<float>(src->vel.y)));
    body->SetAngularVelocity(0.0f);
    b2MassData md;
    md.mass = static_cast<float>(src->mass);
    md.center.SetZero();
    md.I = 0.5f * md.mass * radius * radius;
    body->SetMassData(&md);
}

} // namespace

extern "C" void bench_box2d_init(void)
{
    if (scene != nullptr) return;
    scene = new Scene;
    scene->world.SetWarmStarting(false); /* each collision is a fresh contact */
    scene->world.SetContinuousPhysics(false);
    scene->world.SetAllowSleeping(false);
    for (int i = 0; i < 2; i++) scene->body[i] = make_disk(scene->world, &scene->fixture[i]);
}

extern "C" void bench_box2d_fini(void)
{
    delete scene;
    scene = nullptr;
}

extern "C" c2d_status bench_box2d(c2d_body *a, c2d_body *b, double restitution)
{
    const c2d_body *src[2] = {a, b};
    const double gap = std::hypot(b->pos.x - a->pos.x, b->pos.y - a->pos.y);
    /* Touching with a hair of overlap so float rounding cannot lose the contact. */
    const float radius = static_cast<float>(0.5 * gap * (1.0 + 1e-5));
    const float e = static_cast<float>(restitution);
    for (int i = 0; i < 2; i++) {
        scene->fixture[i]->SetRestitution(e);
        place(scene->body[i], scene->fixture[i], src[i], radius);
    }
    /* A contact that survived from the previous collision keeps its mixed
     * restitution; new ones take the fixtures' values. */
    for (b2Contact *c = scene->world.GetContactList(); c != nullptr; c = c->GetNext()) {
        c->SetRestitution(e);
        c->SetRestitutionThreshold(0.0f);
    }
    scene->world.Step(step_seconds, velocity_iterations, position_iterations);
    const b2Vec2 va = scene->body[0]->GetLinearVelocity(), vb = scene->body[1]->GetLinearVelocity();
    const bool changed = va.x != static_cast<float>(a->vel.x) || va.y != static_cast<float>(a->vel.y) ||
                         vb.x != static_cast<float>(b->vel.x) || vb.y != static_cast<float>(b->vel.y);
    if (!changed) return C2D_SEPARATING;
    a->vel.x = va.x;
    a->vel.y = va.y;
    b->vel.x = vb.x;
    b->vel.y = vb.y;
    return C2D_OK;
}
