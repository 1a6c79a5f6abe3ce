/* SPDX-License-Identifier: MIT */
// engine_view.cpp - see engine_view.h.
#include "app/engine_view.h"

#include <algorithm>
#include <cmath>

namespace demo {

namespace {

constexpr double kCushionRubber = 0.045;  // m, nose line to wood (drawn)
constexpr double kRailBeyondHole = 0.03;  // m of wood (and liner) outside the farthest hole

// The normal of the cushion face whose end is nearest to (x, y).
void nearest_face_normal(const Table &t, double x, double y, double &nx, double &ny) {
    double best = INFINITY;
    nx = ny = 0;
    for (const Segment &s : t.cushions)
        for (const double d : {std::hypot(s.ax - x, s.ay - y), std::hypot(s.bx - x, s.by - y)})
            if (d < best) best = d, nx = s.nx, ny = s.ny;
}

}  // namespace

TableShape table_shape(const Table &table) {
    TableShape shape{table.length, table.width, table.rail, std::min(kCushionRubber, 0.45 * table.rail), table.cushions, {}};
    for (const Pocket &p : table.pockets) {
        PocketShape pocket{p.x, p.y, p.capture_radius, {}};
        for (int k = 0; k < 2; ++k) {
            const Jaw &j = p.jaws[k];
            pocket.jaws[k] = JawShape{j.facing, j.nose_x, j.nose_y, j.nose_r, 0.0, 0.0};
            nearest_face_normal(table, j.nose_x, j.nose_y, pocket.jaws[k].face_nx, pocket.jaws[k].face_ny);
        }
        shape.pockets.push_back(pocket);
        // wide enough for the hole, set back behind the mouth, and its liner
        const double behind = std::max({0.0, -p.x, p.x - table.length, -p.y, p.y - table.width});
        shape.rail = std::max(shape.rail, behind + p.capture_radius + kRailBeyondHole);
    }
    return shape;
}

std::vector<Contact> frame_contacts(const Simulation &sim) {
    std::vector<Contact> out;
    for (const Event &e : sim.frame_events()) {
        switch (e.kind) {
        case EventKind::BallBall:  // one record per ball: sound the pair once
            if (e.ball < e.other) out.push_back({ContactKind::BallBall, e.x, e.y, e.impulse, e.ball, -1});
            break;
        case EventKind::Cushion:
        case EventKind::Jaw: out.push_back({ContactKind::Cushion, e.x, e.y, e.impulse, e.ball, -1}); break;
        case EventKind::Pocket: out.push_back({ContactKind::Pocket, e.x, e.y, e.impulse, e.ball, e.feature}); break;
        case EventKind::Strike: out.push_back({ContactKind::Strike, e.x, e.y, e.impulse, e.ball, -1}); break;
        default: break;
        }
    }
    return out;
}

}  // namespace demo
