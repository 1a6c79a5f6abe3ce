// toi_accel_scaffold.cpp - TEMPORARY, see toi_accel_scaffold.h: sampling and
// bisection, good enough to develop the engine against.
#include "toi_accel_scaffold.h"

#include <cmath>

namespace {

struct Rel {
    double dx, dy, vx, vy, ax, ay, r2;
    double f(double t) const {
        const double x = dx + vx * t + 0.5 * ax * t * t, y = dy + vy * t + 0.5 * ay * t * t;
        return x * x + y * y - r2;
    }
    double df(double t) const {
        const double x = dx + vx * t + 0.5 * ax * t * t, y = dy + vy * t + 0.5 * ay * t * t;
        return x * (vx + ax * t) + y * (vy + ay * t);
    }
};

double bisect(const Rel &r, double lo, double hi) {  // f(lo) > 0 >= f(hi)
    for (int k = 0; k < 200 && hi - lo > 0; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        if (r.f(mid) > 0) lo = mid;
        else hi = mid;
    }
    return hi;
}

}  // namespace

extern "C" c2d_status c2d_time_of_impact_accel(const c2d_body *a, c2d_vec2 acc_a, const c2d_body *b, c2d_vec2 acc_b,
                                               double radius_sum, double horizon, double *t) {
    if (!a || !b || !t || !(radius_sum >= 0) || !(horizon >= 0)) return C2D_INVALID;
    const Rel r{b->pos.x - a->pos.x, b->pos.y - a->pos.y, b->vel.x - a->vel.x, b->vel.y - a->vel.y,
                acc_b.x - acc_a.x, acc_b.y - acc_a.y, radius_sum * radius_sum};
    if (r.f(0) <= 0 && r.df(0) < 0) {
        *t = 0;
        return C2D_OK;
    }
    const double h = std::isinf(horizon) ? 1e3 : horizon;
    const int n = 256;
    double t0 = 0, f0 = r.f(0), d0 = r.df(0);
    if (f0 <= 0) {  // overlapping, not approaching yet: do they turn towards each other while overlapping?
        for (int k = 1; k <= n; ++k) {
            const double t1 = h * k / n;
            if (r.df(t1) < 0) {
                double lo = t0, hi = t1;
                for (int i = 0; i < 200; ++i) {
                    const double mid = 0.5 * (lo + hi);
                    if (mid <= lo || mid >= hi) break;
                    if (r.df(mid) < 0) hi = mid;
                    else lo = mid;
                }
                if (r.f(hi) <= 0) {
                    *t = hi;
                    return C2D_OK;
                }
                if (r.f(t1) <= 0) {  // apart by a hair at hi, overlapping again by t1
                    *t = bisect(r, hi, t1);
                    return C2D_OK;
                }
                break;
            }
            if (r.f(t1) > 0) break;
            t0 = t1;
        }
        t0 = 0;
    }
    for (int k = 1; k <= n; ++k) {
        const double t1 = h * k / n, f1 = r.f(t1), d1 = r.df(t1);
        if (f0 > 0 && f1 <= 0) {
            *t = bisect(r, t0, t1);
            return C2D_OK;
        }
        if (f0 > 0 && d0 < 0 && d1 > 0) {  // a dip inside: find its bottom
            double lo = t0, hi = t1;
            for (int i = 0; i < 200; ++i) {
                const double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi) break;
                if (r.df(mid) < 0) lo = mid;
                else hi = mid;
            }
            if (r.f(lo) <= 0) {
                *t = bisect(r, t0, lo);
                return C2D_OK;
            }
        }
        t0 = t1, f0 = f1, d0 = d1;
    }
    return C2D_SEPARATING;
}
