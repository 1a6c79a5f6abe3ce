/* SPDX-License-Identifier: MIT */
// draw_table.cpp - see draw_table.h.  Every pixel is classified by what lies
// under it (cloth, cushion rubber, hole, leather liner, wood): the playing
// surface [0, L] x [0, W] is cloth; the band of rubber width around it is
// rubber except in a pocket's mouth (the free side of both its jaw facings,
// near the pocket, less the noses' rounding); a hole is the pocket's capture
// circle where there is no rubber; beyond the band is wood.  Where the four
// corners of a pixel disagree it is supersampled 4x4.  Shading is smooth and
// one-dimensional where it can be (across the rails; across the cloth, as
// under a long lamp), so PNG's row filters compress the screenshots well.
#include "app/draw_table.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

// Whether (x, y) lies in the directions from the nose's centre between the
// cushion face's normal and the facing's: towards the arc the balls meet.
bool exposed(const JawShape &j, double x, double y) {
    const double ux = x - j.nose_x, uy = y - j.nose_y;
    const double ax = j.face_nx, ay = j.face_ny, bx = j.facing.nx, by = j.facing.ny;
    const double ab = ax * by - ay * bx, au = ax * uy - ay * ux, ub = ux * by - uy * bx;
    return ab >= 0 ? au >= 0 && ub >= 0 : au <= 0 && ub <= 0;
}

double segment_distance(const Segment &s, double x, double y) {
    const double dx = s.bx - s.ax, dy = s.by - s.ay, len2 = dx * dx + dy * dy;
    const double u = len2 > 0 ? std::clamp(((x - s.ax) * dx + (y - s.ay) * dy) / len2, 0.0, 1.0) : 0.0;
    return std::hypot(x - s.ax - u * dx, y - s.ay - u * dy);
}

// The sharp corner a nose rounds off: behind the cushion face's line and the
// facing's line, near the nose, outside its circle: not rubber.
bool in_nose_rounding(const JawShape &j, double x, double y) {
    if (j.nose_r <= 0) return false;
    const double d = std::hypot(x - j.nose_x, y - j.nose_y);
    if (d <= j.nose_r || d > 2.5 * j.nose_r) return false;
    // the face's line lies nose_r in front of the nose's centre
    const double face = j.face_nx * (x - j.nose_x) + j.face_ny * (y - j.nose_y) - j.nose_r;
    return face < 0 && side_of(j.facing, x, y) < 0 && exposed(j, x, y);
}

// Between a pocket's two facings, short of the line through their throat
// ends, outside the noses (or in the corner a nose rounds off).
bool in_mouth(const PocketShape &p, double x, double y, bool &beyond_throat) {
    if (std::fabs(x - p.x) > 0.4 || std::fabs(y - p.y) > 0.4) return false;  // far from any mouth
    const Segment &f0 = p.jaws[0].facing, &f1 = p.jaws[1].facing;
    const double reach = std::max({std::hypot(f0.ax - p.x, f0.ay - p.y), std::hypot(f1.ax - p.x, f1.ay - p.y),
                                   std::hypot(f0.bx - p.x, f0.by - p.y), std::hypot(f1.bx - p.x, f1.by - p.y)}) +
                         2 * std::max(p.jaws[0].nose_r, p.jaws[1].nose_r) + p.radius;
    if (std::hypot(x - p.x, y - p.y) > reach) return false;
    for (const JawShape &j : p.jaws)
        if (std::hypot(x - j.nose_x, y - j.nose_y) < j.nose_r) return false;
    double tx = f1.by - f0.by, ty = f0.bx - f1.bx;  // across the throat, towards the jaws
    if (tx * (f0.ax - f0.bx) + ty * (f0.ay - f0.by) < 0) tx = -tx, ty = -ty;
    const bool before_throat = tx * (x - f0.bx) + ty * (y - f0.by) >= 0;
    beyond_throat = beyond_throat || !before_throat;
    if (side_of(f0, x, y) >= 0 && side_of(f1, x, y) >= 0 && before_throat) return true;
    return in_nose_rounding(p.jaws[0], x, y) || in_nose_rounding(p.jaws[1], x, y);
}

Stuff stuff_at(const TableShape &t, double x, double y) {
    const bool surface = x >= 0 && y >= 0 && x <= t.length && y <= t.width;
    const double c = t.cushion;
    const bool band = !surface && x >= -c && y >= -c && x <= t.length + c && y <= t.width + c;
    bool mouth = false, hole = false, liner = false, beyond_throat = false;
    for (const PocketShape &p : t.pockets) {
        const double d = std::hypot(x - p.x, y - p.y);
        hole = hole || d < p.radius;
        liner = liner || d < p.radius + kLinerWidth;
        if (!surface && !mouth) mouth = in_mouth(p, x, y, beyond_throat);
    }
    // the cushion ends where its facings do: deeper in, the hole shows
    if (band && !mouth && !(hole && beyond_throat)) return Stuff::Rubber;
    if (hole) return Stuff::Hole;
    if (surface) return Stuff::Cloth;
    if (mouth) return Stuff::Throat;
    return liner ? Stuff::Liner : Stuff::Wood;
}

// Distance outside the playing surface (0 inside).
double outside_distance(const TableShape &t, double x, double y) {
    const double dx = std::max({0.0, -x, x - t.length}), dy = std::max({0.0, -y, y - t.width});
    return std::max(dx, dy);
}

// Distance from a point of rubber to the nearest face a ball touches
// (cushion face, jaw facing, nose): the rubber's profile follows it.
double rubber_depth(const TableShape &t, double x, double y) {
    double e = 1e9;
    for (const Segment &c : t.cushions) e = std::min(e, segment_distance(c, x, y));
    for (const PocketShape &p : t.pockets)
        for (const JawShape &j : p.jaws) {
            e = std::min(e, segment_distance(j.facing, x, y));
            if (j.nose_r > 0 && exposed(j, x, y)) e = std::min(e, std::fabs(std::hypot(x - j.nose_x, y - j.nose_y) - j.nose_r));
        }
    return e;
}

Colour shade(const TableShape &t, const Palette &pal, Stuff stuff, double x, double y) {
    switch (stuff) {
    case Stuff::Cloth: {
        // a long lamp over the table: brightest along its axis; the cushions' shadow
        const double v = (y - t.width / 2) / (t.width / 2);
        const double edge = std::min({x, y, t.length - x, t.width - y});
        const double k = (1.03 - 0.08 * v * v) * (1 - 0.30 * std::exp(-edge / 0.010));
        return scaled(pal.cloth, static_cast<float>(k));
    }
    case Stuff::Throat: {  // the pocket's shelf, darkening towards the hole
        const double depth = std::min(1.0, outside_distance(t, x, y) / (2 * t.cushion));
        return scaled(pal.cloth, static_cast<float>(0.85 - 0.3 * depth));
    }
    case Stuff::Rubber: {
        // the nose's rounded edge, the top catching the light, sloping to the wood
        const double s = rubber_depth(t, x, y) / std::max(1e-9, t.cushion);
        const double k = s < 0.12 ? 0.78 + 3 * s : 1.14 - 0.2 * std::min(1.0, (s - 0.12) / 0.88);
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
    const double half_long = 0.014, half_short = 0.007;
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
    // what lies under each pixel corner, a row at a time (shared by neighbours)
    const int first_x = std::max(0, x0), columns = std::max(0, x1 - first_x);
    std::vector<Stuff> top(static_cast<size_t>(columns) + 1), bottom(top.size());
    auto corners = [&](int py, std::vector<Stuff> &row) {
        for (int k = 0; k <= columns; ++k) row[static_cast<size_t>(k)] = stuff_at(table, v.wx(first_x + k), v.wy(py));
    };
    if (y1 > std::max(0, y0)) corners(std::max(0, y0), top);
    for (int py = std::max(0, y0); py < y1; ++py) {
        corners(py + 1, bottom);
        for (int px = first_x; px < x1; ++px) {
            auto world = [&](double sx, double sy, double &x, double &y) {
                x = v.wx(px + sx);
                y = v.wy(py + sy);
            };
            double x, y;
            world(0.5, 0.5, x, y);
            const Stuff centre = stuff_at(table, x, y);
            const size_t at = static_cast<size_t>(px - first_x);
            const bool uniform = top[at] == centre && top[at + 1] == centre && bottom[at] == centre && bottom[at + 1] == centre;
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
        top.swap(bottom);
    }
    if (style == TableStyle::Pool) {
        draw_diamonds(canvas, table, v, pal.diamond);
        const float spot = std::max(1.5f, v.length(0.004));
        canvas.fill_disk(v.px(0.75 * table.length), v.py(0.5 * table.width), spot, {1, 1, 1}, 0.35f);
    }
}

}  // namespace demo
