/* SPDX-License-Identifier: MIT */
// sphere_contact.cpp - see sphere_contact.h.
#include "pool/sphere_contact.h"

#include <cmath>

extern "C" {
#include "collide2d.h"
}

namespace demo {

namespace {

bool sphere(const Model &m) { return m.contact != ContactModel::Disk; }

// --- spheres -------------------------------------------------------------

c2d_ball ball_of(const Ball &b) {
    return c2d_ball{{b.x, b.y}, {b.vx, b.vy}, {b.wx, b.wy, b.wz}, kBallMass, kBallRadius, kBallInertia};
}

void take(Ball &b, const c2d_ball &s) {
    b.vx = s.vel.x, b.vy = s.vel.y;
    b.wx = s.spin[0], b.wy = s.spin[1], b.wz = s.spin[2];
}

// Walton's beta has no counterpart here: a contact that stops slipping
// stays stopped (beta = 0, today's value).
c2d_ball_surface ball_surface(const Model &m, double restitution) {
    if (m.contact == ContactModel::SphereAlciatore)
        return c2d_ball_surface{restitution, kAlciatoreA, kAlciatoreB, kAlciatoreC};
    return c2d_ball_surface{restitution, m.ball.friction, 0, 0};
}

bool rail_impact(const Model &m, double restitution, Ball &a, double nx, double ny) {
    c2d_ball s = ball_of(a);
    if (c2d_collide_cushion(&s, c2d_cushion{{nx, ny}, m.cushion_height, restitution, m.cushion.friction}) != C2D_OK)
        return false;
    take(a, s);
    return true;
}

// --- disks (the former model) ---------------------------------------------

c2d_surface disk_surface(const Surface &s, double restitution) {
    return c2d_surface{restitution, s.friction, s.tangential_restitution};
}

c2d_disk disk_of(const Ball &b) {
    return c2d_disk{{b.x, b.y}, {b.vx, b.vy}, b.wz, kBallMass, kBallRadius, kBallInertia};
}

c2d_disk fixed_disk(double x, double y, double r) { return c2d_disk{{x, y}, {0, 0}, 0, INFINITY, r, INFINITY}; }

void take(Ball &b, const c2d_disk &d) { b.vx = d.vel.x, b.vy = d.vel.y, b.wz = d.spin; }

}  // namespace

bool collide_balls(const Model &model, double restitution, Ball &a, Ball &b) {
    if (sphere(model)) {
        c2d_ball sa = ball_of(a), sb = ball_of(b);
        if (c2d_collide_balls(&sa, &sb, ball_surface(model, restitution)) != C2D_OK) return false;
        take(a, sa), take(b, sb);
        return true;
    }
    c2d_disk da = disk_of(a), db = disk_of(b);
    if (c2d_collide_rough(&da, &db, disk_surface(model.ball, restitution)) != C2D_OK) return false;
    take(a, da), take(b, db);
    return true;
}

bool collide_face(const Model &model, double restitution, Ball &a, double nx, double ny) {
    if (sphere(model)) return rail_impact(model, restitution, a, nx, ny);
    c2d_disk da = disk_of(a), wall = fixed_disk(a.x + nx * kBallRadius, a.y + ny * kBallRadius, 0);
    if (c2d_collide_rough_normal(&da, &wall, c2d_vec2{nx, ny}, disk_surface(model.cushion, restitution)) != C2D_OK)
        return false;
    take(a, da);
    return true;
}

bool collide_nose(const Model &model, double restitution, Ball &a, double x, double y, double r) {
    if (sphere(model)) return rail_impact(model, restitution, a, x - a.x, y - a.y);
    c2d_disk da = disk_of(a), nose = fixed_disk(x, y, r);
    if (c2d_collide_rough(&da, &nose, disk_surface(model.cushion, restitution)) != C2D_OK) return false;
    take(a, da);
    return true;
}

}  // namespace demo
