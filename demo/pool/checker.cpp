/* SPDX-License-Identifier: MIT */
// checker.cpp - see checker.h.  Between its waypoints a ball moves as the
// engine says it does, p(t) = p0 + v (t - t0) + a (t - t0)^2 / 2 (Box2D's
// balls, and any ball before its first waypoint, move straight between the
// positions the frame starts and ends with), so a pair's relative motion is
// quadratic on each piece between the union of both balls' waypoint times;
// on each piece c2d_time_of_impact_accel tells whether the centres came
// within a diameter.
#include "pool/checker.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

extern "C" {
#include "collide2d.h"
}

#include "pool/det_math.h"

namespace demo {

namespace {

// A ball's path over the frame.
struct Path {
    const Ball *start, *end;
    const Waypoint *bends, *bends_end;
    double dt;
    // Position, velocity and acceleration at t, on the piece that starts at
    // or before t.
    void at(double t, c2d_body &b, c2d_vec2 &acc) const {
        const Waypoint *w = nullptr;
        for (const Waypoint *k = bends; k != bends_end && k->t <= t; ++k) w = k;
        b.mass = kBallMass;
        if (w) {
            const double h = t - w->t;
            b.pos = c2d_vec2{w->x + w->vx * h + 0.5 * w->ax * h * h, w->y + w->vy * h + 0.5 * w->ay * h * h};
            b.vel = c2d_vec2{w->vx + w->ax * h, w->vy + w->ay * h};
            acc = c2d_vec2{w->ax, w->ay};
            return;
        }
        // straight from the frame's start to the first waypoint, or its end
        const double t1 = bends != bends_end ? bends->t : dt;
        const double x1 = bends != bends_end ? bends->x : end->x, y1 = bends != bends_end ? bends->y : end->y;
        const double f = t1 > 0 ? t / t1 : 0.0;
        b.pos = c2d_vec2{start->x + (x1 - start->x) * f, start->y + (y1 - start->y) * f};
        b.vel = t1 > 0 ? c2d_vec2{(x1 - start->x) / t1, (y1 - start->y) / t1} : c2d_vec2{0, 0};
        acc = c2d_vec2{0, 0};
    }
};

// cuts: scratch space, kept between calls.
bool entered(const Path &a, const Path &b, std::vector<double> &cuts) {
    cuts.assign({0.0, a.dt});
    for (const Waypoint *w = a.bends; w != a.bends_end; ++w) cuts.push_back(w->t);
    for (const Waypoint *w = b.bends; w != b.bends_end; ++w) cuts.push_back(w->t);
    std::sort(cuts.begin(), cuts.end());
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double t0 = cuts[k], t1 = cuts[k + 1];
        if (t1 <= t0) continue;
        c2d_body pa, pb;
        c2d_vec2 aa, ab;
        a.at(t0, pa, aa);
        b.at(t0, pb, ab);
        double t;
        // Positions carry rounding: count only a real entry, deeper than
        // 1e-9 of a diameter (a pair that crosses goes a whole diameter deep).
        const double r = kBallDiameter * (1 - 1e-9);
        const bool straight = aa.x == 0 && aa.y == 0 && ab.x == 0 && ab.y == 0;
        if (straight ? c2d_time_of_impact(&pa, &pb, r, &t) == C2D_OK && t < t1 - t0
                     : c2d_time_of_impact_accel(&pa, aa, &pb, ab, r, t1 - t0, &t) == C2D_OK)
            return true;
    }
    return false;
}

// The deepest overlap of a ball with a cushion face, jaw facing or nose, as a
// fraction of a diameter.
double cushion_overlap(const Ball &b, const Table &table) {
    double worst = 0;
    auto face = [&](const Segment &s) {
        const double ex = s.bx - s.ax, ey = s.by - s.ay;
        const double along = (b.x - s.ax) * ex + (b.y - s.ay) * ey;
        if (along < 0 || along > ex * ex + ey * ey) return;
        const double depth = kBallRadius - ((b.x - s.ax) * s.nx + (b.y - s.ay) * s.ny);
        // a ball behind a face has gone through it: as deep as it is behind
        worst = std::max(worst, depth / kBallDiameter);
    };
    for (const Segment &s : table.cushions) face(s);
    for (const Pocket &p : table.pockets)
        for (const Jaw &j : p.jaws) {
            face(j.facing);
            const double dx = b.x - j.nose_x, dy = b.y - j.nose_y, touch = j.nose_r + kBallRadius;
            if (dx * dx + dy * dy < touch * touch)
                worst = std::max(worst, (touch - det_hypot(dx, dy)) / kBallDiameter);
        }
    return worst;
}

}  // namespace

// The waypoints sorted by ball, then time, as a stable sort would: counted
// out by ball (stable, linear), then each ball's few sorted by time if they
// are not already (an engine logs them in time order).
void Checker::index_waypoints(const FrameLog &log, size_t n) {
    first_.assign(n + 1, 0);
    for (const Waypoint &w : log.waypoints) ++first_[static_cast<size_t>(w.ball) + 1];
    for (size_t i = 0; i < n; ++i) first_[i + 1] += first_[i];
    points_.resize(log.waypoints.size());
    fill_.assign(first_.begin(), first_.end() - 1);
    for (const Waypoint &w : log.waypoints) points_[fill_[static_cast<size_t>(w.ball)]++] = w;
    for (size_t i = 0; i < n; ++i) {
        const auto begin = points_.begin() + static_cast<std::ptrdiff_t>(first_[i]);
        const auto end = points_.begin() + static_cast<std::ptrdiff_t>(first_[i + 1]);
        if (!std::is_sorted(begin, end)) std::stable_sort(begin, end);
    }
}

void Checker::bound_paths(const std::vector<Ball> &before, const std::vector<Ball> &after) {
    const size_t n = after.size();
    box_.resize(n);
    live_.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        if (!before[i].active || !after[i].active) continue;
        live_[i] = 1;
        Box &b = box_[i];
        b = {std::min(before[i].x, after[i].x), std::min(before[i].y, after[i].y), std::max(before[i].x, after[i].x),
             std::max(before[i].y, after[i].y), after[i].x, after[i].y};
        for (size_t k = first_[i]; k < first_[i + 1]; ++k) {
            b.x0 = std::min(b.x0, points_[k].x), b.y0 = std::min(b.y0, points_[k].y);
            b.x1 = std::max(b.x1, points_[k].x), b.y1 = std::max(b.y1, points_[k].y);
        }
        b.x0 -= kBallRadius, b.y0 -= kBallRadius, b.x1 += kBallRadius, b.y1 += kBallRadius;
    }
}

// Candidate pairs come from a uniform grid, not from Box2D, so the check
// shares nothing with the engines.  Cells are at least as wide as the
// largest path box: boxes that overlap sit in the same or neighbouring
// cells.  The boxes are copied out in cell order, so the scan reads memory
// in order.  No ball live: no cells (nx_ = 0).
void Checker::build_grid() {
    const size_t n = box_.size();
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY, cell = kBallDiameter;
    for (size_t i = 0; i < n; ++i) {
        if (!live_[i]) continue;
        const Box &b = box_[i];
        x0 = std::min(x0, b.x0), y0 = std::min(y0, b.y0), x1 = std::max(x1, b.x1), y1 = std::max(y1, b.y1);
        cell = std::max(cell, std::max(b.x1 - b.x0, b.y1 - b.y0));
    }
    if (!(x0 <= x1)) {
        nx_ = ny_ = 0;
        return;
    }
    cell = std::max(cell, std::max(x1 - x0, y1 - y0) / 2048);  // bounded grid, whatever the spread
    // about two balls a cell: a sparse gas would otherwise have more cells
    // than balls, and scanning empty cells cost more than testing boxes
    cell = std::max(cell, std::sqrt(2 * (x1 - x0) * (y1 - y0) / static_cast<double>(n)));
    gx0_ = x0, gy0_ = y0, cell_ = cell;
    nx_ = static_cast<size_t>((x1 - x0) / cell) + 1, ny_ = static_cast<size_t>((y1 - y0) / cell) + 1;
    const size_t nx = nx_, ny = ny_;
    cell_of_.resize(n);
    cell_start_.assign(nx * ny + 1, 0);
    auto cell_x = [&](const Box &b) { return std::min(nx - 1, static_cast<size_t>((0.5 * (b.x0 + b.x1) - x0) / cell)); };
    auto cell_y = [&](const Box &b) { return std::min(ny - 1, static_cast<size_t>((0.5 * (b.y0 + b.y1) - y0) / cell)); };
    for (size_t i = 0; i < n; ++i) {
        if (!live_[i]) continue;
        cell_of_[i] = cell_y(box_[i]) * nx + cell_x(box_[i]);
        ++cell_start_[cell_of_[i] + 1];
    }
    for (size_t k = 0; k < nx * ny; ++k) cell_start_[k + 1] += cell_start_[k];
    by_cell_.assign(cell_start_[nx * ny], 0);
    cell_box_.resize(cell_start_[nx * ny]);
    fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
    for (size_t i = 0; i < n; ++i)
        if (live_[i]) {
            by_cell_[fill_[cell_of_[i]]] = i;
            cell_box_[fill_[cell_of_[i]]++] = box_[i];
        }
}

// Every pair of the grid whose boxes overlap, once, lower index first: each
// ball looks at its own cell's later balls and at all balls of the four
// neighbours that follow its cell (east, and the three above), every
// neighbouring pair of cells once.
template <typename Visit>
void Checker::for_each_close_pair(Visit visit) {
    build_grid();
    const size_t nx = nx_, ny = ny_;
    // east, north-west, north, north-east: (dx, dy)
    static const int kForward[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
    auto pair = [&](size_t a, size_t b) {
        const Box &ba = cell_box_[a], &bb = cell_box_[b];
        if (!(ba.x0 <= bb.x1 && bb.x0 <= ba.x1 && ba.y0 <= bb.y1 && bb.y0 <= ba.y1)) return;
        if (by_cell_[a] < by_cell_[b]) visit(by_cell_[a], by_cell_[b], ba, bb);
        else visit(by_cell_[b], by_cell_[a], bb, ba);
    };
    for (size_t cy = 0; cy < ny; ++cy)
        for (size_t cx = 0; cx < nx; ++cx) {
            const size_t own = cy * nx + cx;
            for (size_t a = cell_start_[own]; a < cell_start_[own + 1]; ++a) {
                for (size_t b = a + 1; b < cell_start_[own + 1]; ++b) pair(a, b);
                for (const int *d : kForward) {
                    if ((d[0] < 0 && cx == 0) || (d[0] > 0 && cx + 1 == nx) || (d[1] > 0 && cy + 1 == ny)) continue;
                    const size_t gx = d[0] < 0 ? cx - 1 : cx + static_cast<size_t>(d[0]);
                    const size_t c = (cy + static_cast<size_t>(d[1])) * nx + gx;
                    for (size_t b = cell_start_[c]; b < cell_start_[c + 1]; ++b) pair(a, b);
                }
            }
        }
}

// This frame's sample (checker.h): every stride_-th ball from offset_, the
// offset drawn from the seed and the frame's number (splitmix64), so a run
// checks the same balls every time.
void Checker::choose_sample(size_t n) {
    stride_ = std::max<size_t>(1, (n + kSampledBalls - 1) / kSampledBalls);
    Rng rng(seed_ ^ (0x5851f42d4c957f2dULL * ++frame_));
    offset_ = static_cast<size_t>(rng.next() % stride_);
}

// Every pair with a sampled ball whose boxes overlap, once (lower index
// first): each sampled ball against the balls of the 3 x 3 cells around its
// own; a pair of two sampled balls is taken from the lower one.
template <typename Visit>
void Checker::for_each_sampled_pair(Visit visit) {
    build_grid();
    if (nx_ == 0) return;
    auto sampled = [&](size_t i) { return i % stride_ == offset_; };
    for (size_t i = offset_; i < box_.size(); i += stride_) {
        if (!live_[i]) continue;
        const size_t own = cell_of_[i], cx = own % nx_, cy = own / nx_;
        const Box &bi = box_[i];
        for (size_t y = cy > 0 ? cy - 1 : 0; y <= std::min(ny_ - 1, cy + 1); ++y)
            for (size_t x = cx > 0 ? cx - 1 : 0; x <= std::min(nx_ - 1, cx + 1); ++x) {
                const size_t c = y * nx_ + x;
                for (size_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
                    const size_t j = by_cell_[k];
                    const Box &bj = cell_box_[k];
                    if (j == i || (sampled(j) && j < i)) continue;
                    if (!(bi.x0 <= bj.x1 && bj.x0 <= bi.x1 && bi.y0 <= bj.y1 && bj.y0 <= bi.y1)) continue;
                    if (i < j) visit(i, j, bi, bj);
                    else visit(j, i, bj, bi);
                }
            }
    }
}

// Friction only takes energy; the lossless scenes keep it to rounding.
void Checker::check_energy(const std::vector<Ball> &before, const std::vector<Ball> &after, Stats &stats) const {
    double e0 = 0, e1 = 0;
    for (const Ball &b : before) e0 += energy(b);
    for (const Ball &b : after) e1 += energy(b);
    if (e0 <= 0) return;
    const double change = (e1 - e0) / e0;
    stats.max_energy_step = std::max(stats.max_energy_step, lossless_ ? std::fabs(change) : change);
}

void Checker::count_escaped(const std::vector<Ball> &after, const Table &table, Stats &stats) {
    escaped_.resize(after.size(), 0);
    for (size_t i = 0; i < after.size(); ++i) {
        const Ball &b = after[i];
        const bool outside = !on_table(table, b.x, b.y);
        if (b.active && outside && !escaped_[i]) {
            escaped_[i] = 1;
            ++stats.escaped;
        }
    }
}

void Checker::check_frame(const std::vector<Ball> &before, const std::vector<Ball> &after, FrameLog &log,
                          const Table &table, double dt, Stats &stats) {
    if (mode_ == CheckMode::Off) return;
    index_waypoints(log, after.size());
    bound_paths(before, after);
    for (size_t i = 0; i < after.size(); ++i)
        if (live_[i]) stats.max_overlap = std::max(stats.max_overlap, cushion_overlap(after[i], table));
    std::vector<uint64_t> &resolved = log.contacts;
    std::sort(resolved.begin(), resolved.end());
    auto path = [&](size_t i) {
        return Path{&before[i], &after[i], points_.data() + first_[i], points_.data() + first_[i + 1], dt};
    };
    auto check_pair = [&](size_t i, size_t j, const Box &bi, const Box &bj) {
        ++stats.checked_pairs;
        const double gap = det_hypot(bj.x - bi.x, bj.y - bi.y);
        stats.max_overlap = std::max(stats.max_overlap, (kBallDiameter - gap) / kBallDiameter);
        // crossed: came into contact during the frame and is out the other side
        if (gap > kBallDiameter && entered(path(i), path(j), cuts_) &&
            !std::binary_search(resolved.begin(), resolved.end(), pair_key(static_cast<int>(i), static_cast<int>(j))))
            ++stats.tunnelled;
    };
    if (mode_ == CheckMode::Sample) choose_sample(after.size());
    // every ball sampled (stride 1): the full scan visits the same pairs faster
    if (mode_ == CheckMode::Full || stride_ == 1) for_each_close_pair(check_pair);
    else for_each_sampled_pair(check_pair);
    count_escaped(after, table, stats);
    check_energy(before, after, stats);
}

}  // namespace demo
