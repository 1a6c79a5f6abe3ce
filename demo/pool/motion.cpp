/* SPDX-License-Identifier: MIT */
// motion.cpp - see motion.h.
#include "pool/motion.h"

#include <cmath>

#include "pool/det_math.h"

namespace demo {

const char *motion_name(Motion m) {
    switch (m) {
    case Motion::Stationary: return "stationary";
    case Motion::Spinning: return "spinning";
    case Motion::Sliding: return "sliding";
    case Motion::Rolling: return "rolling";
    default: return "pocketed";
    }
}

Motion classify(const Ball &b) {
    if (!b.active) return Motion::Pocketed;
    if (b.vx - kBallRadius * b.wy != 0 || b.vy + kBallRadius * b.wx != 0) return Motion::Sliding;
    if (b.vx != 0 || b.vy != 0) return Motion::Rolling;
    return b.wz != 0 ? Motion::Spinning : Motion::Stationary;
}

Track make_track(const Ball &b, double t0, const Cloth &cloth, bool friction) {
    Track k{b, t0, INFINITY, 0, 0, 0, 0, 0};
    if (!friction || !b.active) return k;
    const double g = cloth.gravity;
    if (b.wz != 0) k.spin_rate = cloth.spin_deceleration();
    switch (b.motion) {
    case Motion::Sliding: {
        const double ux = b.vx - kBallRadius * b.wy, uy = b.vy + kBallRadius * b.wx;
        const double u = det_hypot(ux, uy);
        const double dec = cloth.slide * g;
        k.ax = -dec * ux / u;
        k.ay = -dec * uy / u;
        k.alpha_x = 2.5 * k.ay / kBallRadius;   // -(5/2) mu_s g u^_y / R
        k.alpha_y = -2.5 * k.ax / kBallRadius;  //  (5/2) mu_s g u^_x / R
        k.t_end = t0 + 2 * u / (7 * dec);
        break;
    }
    case Motion::Rolling: {
        const double v = det_hypot(b.vx, b.vy);
        const double dec = cloth.roll * g;
        k.ax = -dec * b.vx / v;
        k.ay = -dec * b.vy / v;
        k.t_end = t0 + v / dec;
        break;
    }
    case Motion::Spinning: k.t_end = t0 + std::fabs(b.wz) / k.spin_rate; break;
    default: break;
    }
    return k;
}

void position_at(const Track &k, double t, double &x, double &y) {
    const double h = t - k.t0;
    x = k.start.x + k.start.vx * h + 0.5 * k.ax * h * h;
    y = k.start.y + k.start.vy * h + 0.5 * k.ay * h * h;
}

Ball state_at(const Track &k, double t) {
    Ball b = k.start;
    const double h = t - k.t0;
    if (h == 0) return b;
    position_at(k, t, b.x, b.y);
    b.vx += k.ax * h;
    b.vy += k.ay * h;
    if (b.motion == Motion::Rolling) {
        b.wx = -b.vy / kBallRadius;
        b.wy = b.vx / kBallRadius;
    } else {
        b.wx += k.alpha_x * h;
        b.wy += k.alpha_y * h;
    }
    if (k.spin_rate > 0) b.wz = std::copysign(std::fmax(0.0, std::fabs(b.wz) - k.spin_rate * h), b.wz);
    return b;
}

void roll(Ball &b) {
    b.wx = -b.vy / kBallRadius;
    b.wy = b.vx / kBallRadius;
    b.motion = b.vx != 0 || b.vy != 0 ? Motion::Rolling : b.wz != 0 ? Motion::Spinning : Motion::Stationary;
}

Ball state_after_transition(const Track &k) {
    Ball b = state_at(k, k.t_end);
    if (k.start.motion == Motion::Sliding) {
        roll(b);  // u = 0
    } else if (k.start.motion == Motion::Rolling) {
        b.vx = b.vy = b.wx = b.wy = 0;
        b.motion = b.wz != 0 ? Motion::Spinning : Motion::Stationary;
    } else {
        b.wz = 0;
        b.motion = Motion::Stationary;
    }
    return b;
}

double energy(const Ball &b) {
    if (!b.active) return 0;
    return 0.5 * kBallMass * (b.vx * b.vx + b.vy * b.vy) +
           0.5 * kBallInertia * (b.wx * b.wx + b.wy * b.wy + b.wz * b.wz);
}

double squirt_angle(double side, double end_mass) {
    const double across = 1 - side * side;
    return det_atan(2.5 * side * std::sqrt(across) / (1 + kBallMass / end_mass + 2.5 * across));
}

Ball strike(const Ball &b, double angle_rad, double speed, double side, double topback, double elevation_rad,
            double end_mass) {
    Ball s = b;
    const double dx = det_cos(angle_rad), dy = det_sin(angle_rad);
    const double ce = det_cos(elevation_rad), se = det_sin(elevation_rad);
    // the tip's contact point r / R, from the cue's frame (e_right = (dy, -dx, 0))
    const double c = std::sqrt(std::fmax(0.0, 1 - side * side - topback * topback));
    const double rx = side * dy + topback * se * dx - c * ce * dx;
    const double ry = -side * dx + topback * se * dy - c * ce * dy;
    const double rz = topback * ce + c * se;
    // the impulse's direction: the cue's, turned left by the squirt angle
    const double a = squirt_angle(side, end_mass), sx = dx * det_cos(a) - dy * det_sin(a), sy = dy * det_cos(a) + dx * det_sin(a);
    const double jx = ce * sx, jy = ce * sy, jz = -se;
    const double k = 2.5 * speed / (kBallRadius * ce);  // |J| R / I, |J| = m speed / cos(elev)
    s.vx = speed * sx;
    s.vy = speed * sy;
    // (+ 0: a component that cancels is +0, never -0, in the records)
    s.wx = k * (ry * jz - rz * jy) + 0.0;
    s.wy = k * (rz * jx - rx * jz) + 0.0;
    s.wz = k * (rx * jy - ry * jx) + 0.0;
    s.motion = classify(s);
    return s;
}

}  // namespace demo
