/* SPDX-License-Identifier: MIT */
// scene.cpp - see scene.h.  The rack's rows are sqrt(3) radii apart (balls
// touching in a triangle); the gas box's side s holds N disks of radius r at
// area fraction f: N pi r^2 = f s^2.  The cradle's row is one diameter
// apart, centres on one line: each impact's normal lies on the x axis.
#include "pool/scene.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "pool/det_math.h"

namespace demo {

namespace {

constexpr double kGasAreaFraction = 0.1;

Ball make_ball(double x, double y, int number) { return Ball{x, y, 0, 0, number, true}; }

double head_spot_x(const Table &t) { return 0.25 * t.length; }
double centre_line_y(const Table &t) { return 0.5 * t.width; }

// 15 balls in a triangle behind the foot spot: the 1 at the apex, the 8 in
// the middle of the third row, one solid and one stripe in the back corners
// (WPA), the others shuffled by the seed.  The order is the seed's shuffle
// of 2-15 without the 8; if both back corners (the fifth row's ends) are of
// one group, the right one (+y) changes places with the nearest ball of the
// other group before it in the order (in the fifth row if there is one, else
// the fourth, ...; rows read from the apex, each from -y to +y).
// gap > 0 (the break; scene.h, kRackGap): the triangle's pitch is 2 (R + gap)
// instead of 2 R and each ball is moved from its place by a seeded offset
// uniform in the disk of radius gap, so no two balls overlap and neighbours
// are 0 to 4 gap apart (2 gap on average).  The offsets are drawn after the
// shuffle (the order is each seed's as before), by rejection from the
// square, so no trigonometry and the same bits everywhere.
// A ball of the rack at its place plus the seeded offset (rack's comment).
Ball racked(Rng &rng, double x, double y, double gap, int number) {
    double dx = 0, dy = 0;
    if (gap > 0) {
        do {
            dx = 2 * rng.uniform() - 1, dy = 2 * rng.uniform() - 1;
        } while (dx * dx + dy * dy >= 1);
    }
    return make_ball(x + gap * dx, y + gap * dy, number);
}

void rack(std::vector<Ball> &balls, const Table &t, uint64_t seed, double gap) {
    std::vector<int> order = {2, 3, 4, 5, 6, 7, 9, 10, 11, 12, 13, 14, 15};
    Rng rng(seed);
    for (size_t i = order.size() - 1; i > 0; --i)
        std::swap(order[i], order[static_cast<size_t>(rng.next() % (i + 1))]);
    // order[8..12] is the fifth row: corners order[8] and order[12]
    const auto stripe = [](int n) { return n > 8; };
    if (stripe(order[8]) == stripe(order[12])) {
        for (size_t k = 12; k-- > 0;)
            if (k != 8 && stripe(order[k]) != stripe(order[12])) {
                std::swap(order[k], order[12]);
                break;
            }
    }
    const double apex_x = 0.75 * t.length, cy = centre_line_y(t);
    const double pitch = kBallDiameter + 2 * gap, row_step = 0.5 * pitch * std::sqrt(3.0);
    size_t next = 0;
    for (int row = 0; row < 5; ++row) {
        for (int k = 0; k <= row; ++k) {
            int number;
            if (row == 0) number = 1;
            else if (row == 2 && k == 1) number = 8;
            else number = order[next++];
            balls.push_back(racked(rng, apex_x + row * row_step, cy + (k - 0.5 * row) * pitch, gap, number));
        }
    }
}

// 9-ball: balls 1-9 in a diamond (rows of 1, 2, 3, 2, 1) behind the foot
// spot, the 1 at the apex, the 9 in the middle, 2-8 shuffled by the seed;
// the same pitch and seeded offsets as rack's.
void nine_rack(std::vector<Ball> &balls, const Table &t, uint64_t seed, double gap) {
    static const int kRow[5] = {1, 2, 3, 2, 1};
    std::vector<int> order = {2, 3, 4, 5, 6, 7, 8};
    Rng rng(seed);
    for (size_t i = order.size() - 1; i > 0; --i)
        std::swap(order[i], order[static_cast<size_t>(rng.next() % (i + 1))]);
    const double apex_x = 0.75 * t.length, cy = centre_line_y(t);
    const double pitch = kBallDiameter + 2 * gap, row_step = 0.5 * pitch * std::sqrt(3.0);
    size_t next = 0;
    for (int row = 0; row < 5; ++row)
        for (int k = 0; k < kRow[row]; ++k) {
            const int number = row == 0 ? 1 : row == 2 && k == 1 ? 9 : order[next++];
            balls.push_back(racked(rng, apex_x + row * row_step, cy + (k - 0.5 * (kRow[row] - 1)) * pitch, gap, number));
        }
}

void gas(std::vector<Ball> &balls, double side, int count, uint64_t seed) {
    const int per_row = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    const double cell = side / per_row;
    const double jitter = cell / 2 - kBallRadius * 1.01;
    Rng rng(seed);
    double mean_vx = 0, mean_vy = 0;
    for (int i = 0; i < count; ++i) {
        const int column = i % per_row, row = i / per_row; // integer division intended: grid cell
        const double cx = (column + 0.5) * cell, cy = (row + 0.5) * cell;
        Ball b = make_ball(cx + jitter * (2 * rng.uniform() - 1), cy + jitter * (2 * rng.uniform() - 1), i);
        // far from equilibrium on purpose: uniform components, not Gaussian
        b.vx = 2 * rng.uniform() - 1;
        b.vy = 2 * rng.uniform() - 1;
        mean_vx += b.vx;
        mean_vy += b.vy;
        balls.push_back(b);
    }
    mean_vx /= count;
    mean_vy /= count;
    for (Ball &b : balls) {
        b.vx -= mean_vx;
        b.vy -= mean_vy;
        b.motion = classify(b);
    }
}

void cradle(std::vector<Ball> &balls, const Table &t, int count) {
    const double cy = centre_line_y(t);
    balls.push_back(make_ball(head_spot_x(t), cy, 0));
    for (int k = 0; k < count; ++k) balls.push_back(make_ball(0.5 * t.length + k * kBallDiameter, cy, k + 1));
}

}  // namespace

Setup set_up(Scene scene, const TableSpec &spec, int count, uint64_t seed, const std::vector<Placement> &placements) {
    Setup s;
    if (scene == Scene::Gas) {
        const double side = std::sqrt(count * M_PI * kBallRadius * kBallRadius / kGasAreaFraction);
        s.table = closed_box(side, side, std::max(0.05, side / 40));
        gas(s.balls, side, count, seed);
        return s;
    }
    s.table = scene_table(scene, spec);
    if (scene == Scene::Cradle) {
        cradle(s.balls, s.table, count);
        return s;
    }
    if (!placements.empty()) {
        for (const Placement &p : placements) s.balls.push_back(make_ball(p.x, p.y, p.number));
        return s;
    }
    s.balls.push_back(make_ball(head_spot_x(s.table), centre_line_y(s.table), 0));
    rack(s.balls, s.table, seed, scene == Scene::Break ? kRackGap : 0.0);
    return s;
}

Setup set_up_nine_ball(const TableSpec &spec, uint64_t seed) {
    Setup s;
    s.table = pool_table(spec);
    s.balls.push_back(make_ball(head_spot_x(s.table), centre_line_y(s.table), 0));
    nine_rack(s.balls, s.table, seed, kRackGap);
    return s;
}

Table scene_table(Scene scene, const TableSpec &spec) {
    return scene == Scene::Break ? pool_table(spec) : closed_box(spec.length, spec.width, spec.rail);
}

std::string placement_error(const Table &table, const std::vector<Placement> &placements) {
    for (size_t i = 0; i < placements.size(); ++i) {
        const Placement &p = placements[i];
        const std::string name = "ball " + std::to_string(p.number);
        if (p.number < 0 || p.number > 15) return name + ": numbers run from 0 (the cue ball) to 15";
        if (!(p.x >= kBallRadius && p.x <= table.length - kBallRadius && p.y >= kBallRadius &&
              p.y <= table.width - kBallRadius))
            return name + " is not on the table: its centre must be in [R, " + std::to_string(table.length) +
                   " - R] x [R, " + std::to_string(table.width) + " - R], R = " + std::to_string(kBallRadius) + " m";
        for (size_t j = 0; j < i; ++j) {
            const Placement &q = placements[j];
            if (q.number == p.number) return name + " is placed twice";
            // touching within rounding (a rack typed in) is fine
            if (det_hypot(p.x - q.x, p.y - q.y) < kBallDiameter * (1 - 1e-9))
                return name + " overlaps ball " + std::to_string(q.number);
        }
    }
    return "";
}

Point free_head_spot(const Table &table, const std::vector<Ball> &balls) {
    Point p{head_spot_x(table), centre_line_y(table)};
    for (;;) {
        bool free = true;
        for (const Ball &b : balls)
            if (b.active && det_hypot(b.x - p.x, b.y - p.y) < kBallDiameter * 1.01) free = false;
        if (free || p.x < 2 * kBallDiameter) return p;
        p.x -= kBallRadius;
    }
}

}  // namespace demo
