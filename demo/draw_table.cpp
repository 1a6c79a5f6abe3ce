// draw_table.cpp - see draw_table.h.  Every pixel is classified by what lies
// under it (cloth, cushion rubber, hole, leather liner, wood): the playing
// surface [0, L] x [0, W] is cloth; the band of rubber width around it is
// rubber except in a pocket's mouth (the free side of both its jaw facings,
// near the pocket, less the noses' rounding); a hole is the pocket's capture
// circle where there is no rubber; beyond the band is wood.  Where the four
// corners of a pixel disagree it is supersampled 4x4.  Shading is smooth and
// mostly one-dimensional (gradients across the rails, a vignette on the
// cloth), so the compressed screenshots stay small.
#include "draw_table.h"

#include <algorithm>
#include <cmath>

namespace demo {

namespace {

enum class Stuff { Cloth, Throat, Rubber, Hole, Liner, Wood };

constexpr double kLinerWidth = 0.012;  // m, leather around a hole

struct Palette {
    Colour cloth, rubber, wood, hole, liner, diamond;
};

constexpr Palette kPool = {rgb8(28, 118, 66), rgb8(30, 112, 62), rgb8(118, 60, 28), rgb8(6, 6, 6), rgb8(45, 28, 18),
                       rgb8(236, 230, 212)};
constexpr Palette kBox = {rgb8(15, 15, 25), rgb8(45, 45, 58), rgb8(70, 70, 80), rgb8(0, 0, 0), rgb8(0, 0, 0), rgb8(0, 0, 0)};

double side_of(const Segment &s, double x, double y) { return s.nx * (x - s.ax) + s.ny * (y - s.ay); }

double segment_distance(const Segment &s, double x, double y) {
    const double dx = s.bx - s.ax, dy = s.by - s.ay, len2 = dx * dx + dy * dy;
    const double u = len2 > 0 ? std::clamp(((x - s.ax) * dx + (y - s.ay) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(x - s.ax - u * dx, y - s.ay - u * dy);
}

// The sharp corner a nose rounds off: the triangle between the cushion face's
// end, the facing's nose end and the corner where their lines meet, outside
// the nose's circle, is not rubber.
bool in_nose_rounding(const TableShape &t, const JawShape &j, double x, double y) {
    if (j.nose_r <= 0) return false;
    if (std::hypot(x - j.nose_x, y - j.nose_y) <= j.nose_r) return false;
    // the cushion face this nose belongs to: the one whose line is nose_r away
    for (const Segment &c : t.cushions) {
        if (std::fabs(side_of(c, j.nose_x, j.nose_y) + j.nose_r) > 1e-6 + 1e-3 * j.nose_r) continue;
        const double dx = c.bx - c.ax, dy = c.by - c.ay, len2 = dx * dx + dy * dy;
        const double u = len2 > 0 ? ((j.nose_x - c.ax) * dx + (j.nose_y - c.ay) * dy) / len2 : 0;
        if (u < -0.5 || u > 1.5) continue;
        // behind this face, behind the facing, within the nose's box
        if (side_of(c, x, y) < 0 && side_of(j.facing, x, y) < 0 && std::hypot(x - j.nose_x, y - j.nose_y) < 2.5 * j.nose_r)
            return true;
    }
    return false;
}

bool in_mouth(const TableShape &t, const PocketShape &p, double x, double y) {
    const double reach = p.radius + 2 * t.cushion + std::max(p.jaws[0].nose_r, p.jaws[1].nose_r);
    if (std::hypot(x - p.x, y - p.y) > reach + std::hypot(p.jaws[0].facing.ax - p.x, p.jaws[0].facing.ay - p.y)) return false;
    for (const JawShape &j : p.jaws)
        if (std::hypot(x - j.nose_x, y - j.nose_y) < j.nose_r) return false;
    if (side_of(p.jaws[0].facing, x, y) >= 0 && side_of(p.jaws[1].facing, x, y) >= 0) return true;
    return in_nose_rounding(t, p.jaws[0], x, y) || in_nose_rounding(t, p.jaws[1], x, y);
}

Stuff stuff_at(const TableShape &t, double x, double y) {
    const bool surface = x >= 0 && y >= 0 && x <= t.length && y <= t.width;
    const double c = t.cushion;
    const bool band = !surface && x >= -c && y >= -c && x <= t.length + c && y <= t.width + c;
    bool mouth = false, hole = false, liner = false;
    for (const PocketShape &p : t.pockets) {
        const double d = std::hypot(x - p.x, y - p.y);
        hole = hole || d < p.radius;
        liner = liner || d < p.radius + kLinerWidth;
        if (band && !mouth) mouth = in_mouth(t, p, x, y);
    }
    if (band && !mouth) return Stuff::Rubber;
    if (hole) return Stuff::Hole;
    if (surface) return Stuff::Cloth;
    if (band) return Stuff::Throat;
    return liner ? Stuff::Liner : Stuff::Wood;
}

// Distance outside the playing surface (0 inside).
double outside_distance(const TableShape &t, double x, double y) {
    const double dx = std::max({0.0, -x, x - t.length}), dy = std::max({0.0, -y, y - t.width});
    return std::max(dx, dy);
}

Colour shade(const TableShape &t, const Palette &pal, Stuff stuff, double x, double y) {
    switch (stuff) {
    case Stuff::Cloth: {
        const double u = (x - t.length / 2) / (t.length / 2), v = (y - t.width / 2) / (t.width / 2);
        const double edge = std::min({x, y, t.length - x, t.width - y});
        const double k = (1.04 - 0.07 * u * u - 0.07 * v * v) * (1 - 0.30 * std::exp(-edge / 0.010));
        return scaled(pal.cloth, static_cast<float>(k));
    }
    case Stuff::Throat: return scaled(pal.cloth, 0.62f);
    case Stuff::Rubber: {
        // the nose's rounded edge, the top catching the light, sloping to the wood
        const double s = outside_distance(t, x, y) / std::max(1e-9, t.cushion);
        double k = s < 0.12 ? 0.78 + 3 * s : 1.14 - 0.2 * (s - 0.12) / 0.88;
        for (const PocketShape &p : t.pockets)  // the jaw facings are walls, in shade
            for (const JawShape &j : p.jaws) k *= 0.72 + 0.28 * std::min(1.0, segment_distance(j.facing, x, y) / 0.01);
        return scaled(pal.rubber, static_cast<float>(k));
    }
    case Stuff::Hole: {
        double k = 1;
        for (const PocketShape &p : t.pockets) {
            const double d = std::hypot(x - p.x, y - p.y) / p.radius;
            if (d < 1) k = std::min(k, 0.3 + 0.7 * d * d);
        }
        return scaled(pal.hole, static_cast<float>(2 * k));
    }
    case Stuff::Liner: return pal.liner;
    case Stuff::Wood: break;
    }
    const double wood = std::max(1e-9, t.rail - t.cushion);
    const double s = std::clamp((outside_distance(t, x, y) - t.cushion) / wood, 0.0, 1.0);  // 0 inner, 1 outer edge
    double k = 1.18 - 0.3 * s;
    if (s < 0.06) k *= 0.78 + 3.6 * s;        // the step down to the cushion
    if (s > 0.9) k *= 1 - 3.0 * (s - 0.9);    // the rounded outer edge
    k *= 1 + 0.035 * std::sin(s * 41.0) + 0.02 * std::sin(s * 97.0);  // faint grain along the rail
    return scaled(pal.wood, static_cast<float>(k));
}

void draw_diamonds(Canvas &canvas, const TableShape &t, const View &v, Colour colour) {
    const double off = t.cushion + 0.5 * (t.rail - t.cushion);  // the wood's centre line
    const double half_long = 0.011, half_short = 0.0055;
    auto diamond = [&](double x, double y, bool along_x) {
        const double ax = along_x ? half_long : half_short, ay = along_x ? half_short : half_long;
        canvas.fill_convex({v.at(x - ax, y), v.at(x, y + ay), v.at(x + ax, y), v.at(x, y - ay)}, colour, 0.95f);
    };
    for (int i = 1; i < 8; ++i) {
        if (i == 4) continue;  // the side pockets
        const double x = t.length * i / 8.0;
        diamond(x, -off, true);
        diamond(x, t.width + off, true);
    }
    for (int j = 1; j < 4; ++j) {
        const double y = t.width * j / 4.0;
        diamond(-off, y, false);
        diamond(t.length + off, y, false);
    }
}

}  // namespace

void draw_table(Canvas &canvas, const TableShape &table, const Screen &layout, TableStyle style) {
    canvas.clear({0, 0, 0});
    const Palette &pal = style == TableStyle::Pool ? kPool : kBox;
    const View &v = layout.view;
    const int x0 = static_cast<int>(layout.table.x), y0 = static_cast<int>(layout.table.y);
    const int x1 = std::min(canvas.width(), static_cast<int>(std::ceil(layout.table.x + layout.table.w)));
    const int y1 = std::min(canvas.height(), static_cast<int>(std::ceil(layout.table.y + layout.table.h)));
    for (int py = std::max(0, y0); py < y1; ++py)
        for (int px = std::max(0, x0); px < x1; ++px) {
            auto world = [&](double sx, double sy, double &x, double &y) {
                x = v.wx(px + sx);
                y = v.wy(py + sy);
            };
            double x, y;
            world(0.5, 0.5, x, y);
            const Stuff centre = stuff_at(table, x, y);
            bool uniform = true;
            for (int k = 0; k < 4 && uniform; ++k) {
                double cx, cy;
                world(k & 1 ? 0.9 : 0.1, k & 2 ? 0.9 : 0.1, cx, cy);
                uniform = stuff_at(table, cx, cy) == centre;
            }
            if (uniform) {
                canvas.put(px, py, shade(table, pal, centre, x, y));
                continue;
            }
            Colour sum{0, 0, 0};
            for (int k = 0; k < 16; ++k) {
                double sx, sy;
                world(0.125 + 0.25 * (k % 4), 0.125 + 0.25 * (k / 4), sx, sy);  // NOLINT(bugprone-integer-division)
                const Colour c = shade(table, pal, stuff_at(table, sx, sy), sx, sy);
                sum = {sum.r + c.r / 16, sum.g + c.g / 16, sum.b + c.b / 16};
            }
            canvas.put(px, py, sum);
        }
    if (style == TableStyle::Pool) {
        draw_diamonds(canvas, table, v, pal.diamond);
        const float spot = std::max(1.5f, v.length(0.004));
        canvas.fill_disk(v.px(0.75 * table.length), v.py(0.5 * table.width), spot, {1, 1, 1}, 0.35f);
    }
}

}  // namespace demo
