/* SPDX-License-Identifier: MIT */
// slow_contact.cpp - see slow_contact.h.
#include "pool/slow_contact.h"

#include <cmath>
#include <utility>

#include "pool/det_math.h"

namespace demo {

bool within(double x, double y, const std::vector<Limit> &limits) {
    for (const Limit &l : limits)
        if (x * l.nx + y * l.ny > l.c + kGraze) return false;
    return true;
}

void nearest_within(double &x, double &y, const std::vector<Limit> &limits) {
    if (within(x, y, limits)) return;
    std::vector<std::pair<double, double>> candidates = {{0.0, 0.0}};
    for (const Limit &l : limits) {
        const double over = x * l.nx + y * l.ny - l.c;
        candidates.emplace_back(x - over * l.nx, y - over * l.ny);
    }
    for (size_t k = 0; k < limits.size(); ++k)
        for (size_t m = k + 1; m < limits.size(); ++m) {
            const Limit &p = limits[k], &q = limits[m];
            const double det = p.nx * q.ny - p.ny * q.nx;
            if (std::fabs(det) > 1e-9)
                candidates.emplace_back((p.c * q.ny - q.c * p.ny) / det, (p.nx * q.c - q.nx * p.c) / det);
        }
    double best = INFINITY, bx = 0, by = 0;
    for (const auto &cand : candidates) {
        const double far = det_hypot(cand.first - x, cand.second - y);
        if (far < best && within(cand.first, cand.second, limits)) best = far, bx = cand.first, by = cand.second;
    }
    x = bx, y = by;
}

bool same_motion(const Ball &a, const Ball &b) {
    return a.vx == b.vx && a.vy == b.vy && a.wx == b.wx && a.wy == b.wy && a.wz == b.wz;
}

Ball slid(Ball b) {
    if (b.motion != Motion::Sliding) return b;
    const double ux = b.vx - kBallRadius * b.wy, uy = b.vy + kBallRadius * b.wx;
    b.vx -= 2.0 / 7 * ux;
    b.vy -= 2.0 / 7 * uy;
    roll(b);
    return b;
}

}  // namespace demo
