/* SPDX-License-Identifier: MIT */
// table.cpp - see table.h.  Each pocket is built from its two theoretical
// jaw points P (on the cushion lines, `mouth` apart) and, for each, e: the
// unit vector along the rail away from the pocket and n: the rail's normal
// into the table.  The facing leaves P at the facing angle phi from e, on
// the rubber's side: d = cos(phi) e - sin(phi) n.  The nose is the circle of
// radius r tangent to both lines: centre P + r / sin(phi/2) (e + d)/|e + d|,
// touching them r / tan(phi/2) from P.  The facing runs from that tangent
// point to the depth (along the pocket's axis a, from the mouth line) of
// the hole's centre, shelf + hole_radius: lambda = depth / (d.a).  The rail
// cushions run between the noses' tangent points on each rail.
#include "pool/table.h"

#include <cmath>

#include "pool/det_math.h"

namespace demo {

namespace {

struct Vec { double x, y; };

Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y}; }
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y}; }
Vec operator*(double s, Vec a) { return {s * a.x, s * a.y}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y; }
Vec unit(Vec a) { return (1.0 / det_hypot(a.x, a.y)) * a; }

// A theoretical jaw point with its rail.
struct JawPoint { Vec p, e, n; };

// Where a rail's cushion face ends at a nose.
struct RailEnd { Vec t, e, n; };

Segment segment(Vec a, Vec b, Vec n) { return Segment{a.x, a.y, b.x, b.y, n.x, n.y}; }

Pocket make_pocket(const JawPoint (&jp)[2], Vec axis, const PocketSpec &s, std::vector<RailEnd> &ends) {
    const double phi = s.facing_angle_deg * (M_PI / 180.0);
    const Vec mid = 0.5 * (jp[0].p + jp[1].p);
    const double depth = s.shelf + s.hole_radius;
    const Vec hole = mid + depth * axis;
    Pocket pocket{hole.x, hole.y, s.hole_radius, {}, {}};
    for (int k = 0; k < 2; ++k) {
        const JawPoint &j = jp[k];
        const Vec d = det_cos(phi) * j.e - det_sin(phi) * j.n;
        Vec fn{-d.y, d.x};
        if (dot(fn, mid - j.p) < 0) fn = -1.0 * fn;
        const double along = s.nose_radius / det_tan(phi / 2);
        const Vec nose = j.p + (s.nose_radius / det_sin(phi / 2)) * unit(j.e + d);
        const Vec throat = j.p + (depth / dot(d, axis)) * d;
        pocket.jaws[k] = Jaw{segment(j.p + along * d, throat, fn), nose.x, nose.y, s.nose_radius};
        pocket.mouth[k] = Point{j.p.x, j.p.y};
        ends.push_back(RailEnd{j.p + along * j.e, j.e, j.n});
    }
    return pocket;
}

// Joins each rail end to the nearest one facing it along the same rail.
void add_rail_cushions(Table &t, const std::vector<RailEnd> &ends) {
    for (size_t i = 0; i < ends.size(); ++i) {
        const RailEnd &a = ends[i];
        const RailEnd *best = nullptr;
        double best_distance = INFINITY;
        for (size_t j = i + 1; j < ends.size(); ++j) {
            const RailEnd &b = ends[j];
            const double ahead = dot(b.t - a.t, a.e);
            const bool same_rail = dot(a.n, b.n) > 0.5 && std::fabs(dot(b.t - a.t, a.n)) < 1e-12;
            if (same_rail && dot(a.e, b.e) < -0.5 && ahead > 0 && ahead < best_distance) {
                best = &b;
                best_distance = ahead;
            }
        }
        if (best) t.cushions.push_back(segment(a.t, best->t, a.n));
    }
}

// p inside the convex polygon q[0..3] (either orientation).
bool in_convex(const Vec (&q)[4], Vec p) {
    int sign = 0;
    for (int k = 0; k < 4; ++k) {
        const Vec a = q[k], b = q[(k + 1) % 4];
        const double c = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        const int s = c > 0 ? 1 : c < 0 ? -1 : 0;
        if (s != 0 && sign != 0 && s != sign) return false;
        if (s != 0) sign = s;
    }
    return true;
}

}  // namespace

Table pool_table(const TableSpec &spec) {
    Table t{spec.length, spec.width, spec.rail, {}, {}};
    const double L = spec.length, W = spec.width;
    std::vector<RailEnd> ends;
    const double a = spec.corner.mouth / std::sqrt(2.0);  // corner jaw points, from the corner along each rail
    for (double cy : {0.0, W})
        for (double cx : {0.0, L}) {
            const double sx = cx == 0.0 ? 1.0 : -1.0, sy = cy == 0.0 ? 1.0 : -1.0;
            const JawPoint jp[2] = {{{cx + sx * a, cy}, {sx, 0}, {0, sy}}, {{cx, cy + sy * a}, {0, sy}, {sx, 0}}};
            t.pockets.push_back(make_pocket(jp, unit({-sx, -sy}), spec.corner, ends));
        }
    const double h = spec.side.mouth / 2;
    for (double cy : {0.0, W}) {
        const double sy = cy == 0.0 ? 1.0 : -1.0;
        const JawPoint jp[2] = {{{L / 2 - h, cy}, {-1, 0}, {0, sy}}, {{L / 2 + h, cy}, {1, 0}, {0, sy}}};
        t.pockets.push_back(make_pocket(jp, {0, -sy}, spec.side, ends));
    }
    add_rail_cushions(t, ends);
    return t;
}

Table closed_box(double length, double width, double rail) {
    Table t{length, width, rail, {}, {}};
    t.cushions.push_back(segment({0, 0}, {length, 0}, {0, 1}));
    t.cushions.push_back(segment({0, width}, {length, width}, {0, -1}));
    t.cushions.push_back(segment({0, 0}, {0, width}, {1, 0}));
    t.cushions.push_back(segment({length, 0}, {length, width}, {-1, 0}));
    return t;
}

bool in_pocket_mouth(const Pocket &pocket, double x, double y) {
    const Vec p{x, y};
    if (det_hypot(x - pocket.x, y - pocket.y) <= pocket.capture_radius) return true;
    const Segment &f0 = pocket.jaws[0].facing, &f1 = pocket.jaws[1].facing;
    const Vec quad[4] = {{pocket.mouth[0].x, pocket.mouth[0].y}, {f0.bx, f0.by}, {f1.bx, f1.by},
                         {pocket.mouth[1].x, pocket.mouth[1].y}};
    return in_convex(quad, p);
}

bool on_table(const Table &table, double x, double y) {
    if (x >= 0 && x <= table.length && y >= 0 && y <= table.width) return true;
    for (const Pocket &p : table.pockets)
        if (in_pocket_mouth(p, x, y)) return true;
    return false;
}

}  // namespace demo
