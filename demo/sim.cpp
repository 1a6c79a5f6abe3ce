// sim.cpp - see sim.h; and the independent frame checker.
#include "sim.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "box2d_engine.h"
#include "exact_engine.h"

extern "C" {
#include "collide2d.h"
}

namespace demo {

namespace {

constexpr double kStopSpeed = 0.01;            // m/s

}  // namespace

// ------------------------------------------------------------------ checker

// Independent of the engines: each frame, every pair whose motion during the
// frame brings them into contact (c2d_time_of_impact on each straight piece
// of the two paths) and out the other side, without a contact the engine
// resolved, is a tunnelled pair.  Overlaps are measured at the frame's end.
struct Simulation::Checker {
    struct Box { double x0, y0, x1, y1; };
    std::vector<Box> box;              // each live ball's path this frame, plus its radius
    std::vector<char> live;
    std::vector<Waypoint> points;      // this frame's waypoints, sorted by ball then time
    std::vector<size_t> first;         // points[first[i] .. first[i+1]) belong to ball i
    std::vector<size_t> cell_of, cell_start, by_cell;
};

namespace {

// A ball's path over the frame: straight pieces between its waypoints.
struct Path {
    const Ball *start, *end;
    const Waypoint *bends, *bends_end;
    double dt;
    void at(double t, double &x, double &y) const {
        double t0 = 0, x0 = start->x, y0 = start->y;
        const Waypoint *w = bends;
        while (w != bends_end && w->t <= t) {
            t0 = w->t, x0 = w->x, y0 = w->y;
            ++w;
        }
        const double t1 = w != bends_end ? w->t : dt;
        const double x1 = w != bends_end ? w->x : end->x, y1 = w != bends_end ? w->y : end->y;
        const double f = t1 > t0 ? (t - t0) / (t1 - t0) : 0.0;
        x = x0 + (x1 - x0) * f;
        y = y0 + (y1 - y0) * f;
    }
};

void piece_body(const Path &p, double t0, double t1, c2d_body &b) {
    double x1, y1;
    p.at(t0, b.pos.x, b.pos.y);
    // the position just before t1 (a bend at t1 starts the next piece)
    const Waypoint *w = p.bends;
    while (w != p.bends_end && w->t < t1) ++w;
    if (w != p.bends_end && w->t == t1) x1 = w->x, y1 = w->y;
    else p.at(t1, x1, y1);
    b.vel.x = (x1 - b.pos.x) / (t1 - t0);
    b.vel.y = (y1 - b.pos.y) / (t1 - t0);
    b.mass = kBallMass;
}

bool entered(const Path &a, const Path &b) {
    std::vector<double> cuts = {0.0, a.dt};
    for (const Waypoint *w = a.bends; w != a.bends_end; ++w) cuts.push_back(w->t);
    for (const Waypoint *w = b.bends; w != b.bends_end; ++w) cuts.push_back(w->t);
    std::sort(cuts.begin(), cuts.end());
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double t0 = cuts[k], t1 = cuts[k + 1];
        if (t1 <= t0) continue;
        c2d_body pa, pb;
        piece_body(a, t0, t1, pa);
        piece_body(b, t0, t1, pb);
        double t;
        // Positions carry rounding, and a piece can be 1e-17 s long, so its
        // velocity is noise: count only a real entry, deeper than 1e-9 of a
        // diameter (a pair that crosses goes a whole diameter deep).
        if (c2d_time_of_impact(&pa, &pb, kBallDiameter * (1 - 1e-9), &t) == C2D_OK && t < t1 - t0) return true;
    }
    return false;
}

double cushion_overlap(const Ball &b, const Table &table) {
    double worst = 0;
    for (const Segment &s : table.cushions) {
        const double ex = s.bx - s.ax, ey = s.by - s.ay;
        const double along = (b.x - s.ax) * ex + (b.y - s.ay) * ey;
        if (along < 0 || along > ex * ex + ey * ey) continue;
        const double depth = kBallRadius - ((b.x - s.ax) * s.nx + (b.y - s.ay) * s.ny);
        worst = std::max(worst, depth / kBallDiameter);
    }
    return worst;
}

}  // namespace

void Simulation::index_waypoints(size_t n) {
    Checker &c = *checker_;
    c.points = frame_log_->waypoints;
    std::stable_sort(c.points.begin(), c.points.end());
    c.first.assign(n + 1, 0);
    for (const Waypoint &w : c.points) ++c.first[static_cast<size_t>(w.ball) + 1];
    for (size_t i = 0; i < n; ++i) c.first[i + 1] += c.first[i];
}

// Candidate pairs for the checker come from a uniform grid, not from Box2D,
// so the check shares nothing with the engines.  Cells are at least as wide
// as the largest path box: boxes that overlap sit in neighbouring cells.
template <typename Visit>
void Simulation::for_each_close_pair(Visit visit) {
    Checker &c = *checker_;
    const size_t n = c.box.size();
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY, cell = kBallDiameter;
    for (size_t i = 0; i < n; ++i) {
        if (!c.live[i]) continue;
        const Checker::Box &b = c.box[i];
        x0 = std::min(x0, b.x0), y0 = std::min(y0, b.y0), x1 = std::max(x1, b.x1), y1 = std::max(y1, b.y1);
        cell = std::max(cell, std::max(b.x1 - b.x0, b.y1 - b.y0));
    }
    if (!(x0 <= x1)) return;
    cell = std::max(cell, std::max(x1 - x0, y1 - y0) / 2048);  // bounded grid, whatever the spread
    const size_t nx = static_cast<size_t>((x1 - x0) / cell) + 1, ny = static_cast<size_t>((y1 - y0) / cell) + 1;
    c.cell_of.assign(n, 0);
    c.cell_start.assign(nx * ny + 1, 0);
    auto cell_x = [&](const Checker::Box &b) { return std::min(nx - 1, static_cast<size_t>((0.5 * (b.x0 + b.x1) - x0) / cell)); };
    auto cell_y = [&](const Checker::Box &b) { return std::min(ny - 1, static_cast<size_t>((0.5 * (b.y0 + b.y1) - y0) / cell)); };
    for (size_t i = 0; i < n; ++i) {
        if (!c.live[i]) continue;
        c.cell_of[i] = cell_y(c.box[i]) * nx + cell_x(c.box[i]);
        ++c.cell_start[c.cell_of[i] + 1];
    }
    for (size_t k = 0; k < nx * ny; ++k) c.cell_start[k + 1] += c.cell_start[k];
    c.by_cell.assign(c.cell_start[nx * ny], 0);
    std::vector<size_t> fill(c.cell_start.begin(), c.cell_start.end() - 1);
    for (size_t i = 0; i < n; ++i)
        if (c.live[i]) c.by_cell[fill[c.cell_of[i]]++] = i;
    for (size_t i = 0; i < n; ++i) {
        if (!c.live[i]) continue;
        const Checker::Box &bi = c.box[i];
        const size_t cx = c.cell_of[i] % nx, cy = c.cell_of[i] / nx;
        for (size_t gy = cy ? cy - 1 : 0; gy <= std::min(ny - 1, cy + 1); ++gy)
            for (size_t gx = cx ? cx - 1 : 0; gx <= std::min(nx - 1, cx + 1); ++gx)
                for (size_t k = c.cell_start[gy * nx + gx]; k < c.cell_start[gy * nx + gx + 1]; ++k) {
                    const size_t j = c.by_cell[k];
                    const Checker::Box &bj = c.box[j];
                    if (j > i && bi.x0 <= bj.x1 && bj.x0 <= bi.x1 && bi.y0 <= bj.y1 && bj.y0 <= bi.y1) visit(i, j);
                }
    }
}

void Simulation::check_frame(const std::vector<Ball> &before, double dt) {
    const std::vector<Ball> &after = engine_->balls_;
    Checker &c = *checker_;
    const size_t n = after.size();
    index_waypoints(n);
    c.box.resize(n);
    c.live.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        if (!before[i].active || !after[i].active) continue;
        c.live[i] = 1;
        Checker::Box &b = c.box[i];
        b = {std::min(before[i].x, after[i].x), std::min(before[i].y, after[i].y), std::max(before[i].x, after[i].x),
             std::max(before[i].y, after[i].y)};
        for (size_t k = c.first[i]; k < c.first[i + 1]; ++k) {
            b.x0 = std::min(b.x0, c.points[k].x), b.y0 = std::min(b.y0, c.points[k].y);
            b.x1 = std::max(b.x1, c.points[k].x), b.y1 = std::max(b.y1, c.points[k].y);
        }
        b.x0 -= kBallRadius, b.y0 -= kBallRadius, b.x1 += kBallRadius, b.y1 += kBallRadius;
        stats_.max_overlap = std::max(stats_.max_overlap, cushion_overlap(after[i], table_));
    }
    std::vector<uint64_t> &resolved = frame_log_->contacts;
    std::sort(resolved.begin(), resolved.end());
    auto path = [&](size_t i) {
        return Path{&before[i], &after[i], c.points.data() + c.first[i], c.points.data() + c.first[i + 1], dt};
    };
    for_each_close_pair([&](size_t i, size_t j) {
        const double gap = std::hypot(after[j].x - after[i].x, after[j].y - after[i].y);
        stats_.max_overlap = std::max(stats_.max_overlap, (kBallDiameter - gap) / kBallDiameter);
        // crossed: came into contact during the frame and is out the other side
        if (gap > kBallDiameter && entered(path(i), path(j)) &&
            !std::binary_search(resolved.begin(), resolved.end(), pair_key(static_cast<int>(i), static_cast<int>(j))))
            ++stats_.tunnelled;
    });
}

// ---------------------------------------------------------------- simulation

Simulation::Simulation(const SimConfig &config) : config_(config), frame_log_(new FrameLog), checker_(new Checker) {
    Layout start = set_up(config.scene, config.gas_balls, config.seed);
    table_ = std::move(start.table);
    balls_initial_ = std::move(start.balls);
    if (config.response == Response::Box2d)
        engine_ = make_box2d_engine(balls_initial_, table_, config.losses.restitution);
    else
        engine_ = make_exact_engine(balls_initial_, table_, config.losses.restitution);
    escaped_flag_.assign(balls_initial_.size(), 0);
}

Simulation::~Simulation() = default;

const std::vector<Ball> &Simulation::balls() const { return engine_->balls_; }

bool Simulation::cue_on_table() const {
    return config_.scene != Scene::Gas && engine_->balls_[0].active;
}

void Simulation::shoot(const Shot &shot) {
    if (!cue_on_table()) return;
    const double a = shot.angle_deg * (M_PI / 180.0);
    engine_->balls_[0].vx = shot.speed * std::cos(a);
    engine_->balls_[0].vy = shot.speed * std::sin(a);
    engine_->velocities_changed();
}

bool Simulation::at_rest() const {
    for (const Ball &b : engine_->balls_)
        if (b.active && (b.vx != 0 || b.vy != 0)) return false;
    return true;
}

int Simulation::object_balls_left() const {
    int left = 0;
    for (const Ball &b : engine_->balls_) left += b.active && b.number != 0;
    return left;
}

void Simulation::respot_cue() {
    Ball &cue = engine_->balls_[0];
    if (cue.active || config_.scene == Scene::Gas) return;
    const Point spot = free_head_spot(table_, engine_->balls_);
    cue = Ball{spot.x, spot.y, 0, 0, 0, true};
    engine_->ball_placed(0);
}

double Simulation::energy() const {
    double e = 0;
    for (const Ball &b : engine_->balls_)
        if (b.active) e += 0.5 * kBallMass * (b.vx * b.vx + b.vy * b.vy);
    return e;
}

void Simulation::momentum(double out[2]) const {
    out[0] = out[1] = 0;
    for (const Ball &b : engine_->balls_)
        if (b.active) {
            out[0] += kBallMass * b.vx;
            out[1] += kBallMass * b.vy;
        }
}

void Simulation::count_escaped() {
    const std::vector<Ball> &all = engine_->balls_;
    for (size_t i = 0; i < all.size(); ++i) {
        const Ball &b = all[i];
        const bool outside = b.x < 0 || b.x > table_.length || b.y < 0 || b.y > table_.width;
        if (b.active && outside && !escaped_flag_[i]) {
            escaped_flag_[i] = 1;
            ++stats_.escaped;
        }
    }
}

void Simulation::step() {
    const std::vector<Ball> before = engine_->balls_;
    frame_log_->contacts.clear();
    frame_log_->waypoints.clear();
    engine_->step(kFrameDt, stats_, *frame_log_);
    check_frame(before, kFrameDt);
    count_escaped();
    if (config_.losses.rolling_deceleration > 0) {
        // rolling resistance changes velocities only between frames, so the
        // motion inside a frame stays straight and its impacts exact
        for (Ball &b : engine_->balls_) {
            const double speed = std::hypot(b.vx, b.vy);
            if (speed == 0) continue;
            const double slower = speed - config_.losses.rolling_deceleration * kFrameDt;
            const double scale = slower < kStopSpeed ? 0.0 : slower / speed;
            b.vx *= scale;
            b.vy *= scale;
        }
        engine_->velocities_changed();
    }
    ++stats_.steps;
    stats_.sim_seconds = static_cast<double>(stats_.steps) * kFrameDt;
}

}  // namespace demo
