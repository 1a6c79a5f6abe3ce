/* SPDX-License-Identifier: MIT */
// world_engine.cpp - see world_engine.h.
//
// The table's closed box is the world's box (C2D_WALLS): its four cushion
// faces are the world's walls, met exactly and resolved by the world
// (the normal component negated times the cushion's restitution).  Ball i
// is disk world_index_[i]; a ball put back on the table (place_ball) makes
// a new world with every ball on the table (the table is at rest then), so
// indices are the world's from its own start: ball_of_ maps them back.
// The world's own clock runs from 0 at its start; epoch_ is the simulated
// time of that start.
//
// What the world reports becomes the demo's records as the exact engine
// made them: a ball-ball impact two Event records (the lower-numbered ball
// first) with each ball's state after it and the impulse's magnitude, a
// wall a cushion record (feature: the cushion's index in Table::cushions),
// and for the checker the pair (FrameLog::contacts) and each changed ball's
// state at the event (a waypoint: between events the balls move straight).
#include "pool/world_engine.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

extern "C" {
#include "collide2d_world.h"
}

namespace demo {

namespace {

constexpr size_t kNoDisk = std::numeric_limits<size_t>::max();

// The world's walls 0..3 are x = 0, x = width, y = 0, y = height;
// closed_box's cushions are y = 0, y = width, x = 0, x = length.
constexpr int kCushionOfWall[4] = {2, 3, 0, 1};

// The box's cushions as closed_box makes them: the table's rectangle.
bool is_closed_box(const Table &table) {
    const std::vector<Segment> &c = table.cushions;
    return table.pockets.empty() && c.size() == 4 && c[0].ay == 0 && c[0].by == 0 && c[1].ay == table.width &&
           c[2].ax == 0 && c[2].bx == 0 && c[3].ax == table.length;
}

class WorldEngine : public Engine {
public:
    WorldEngine(const std::vector<Ball> &balls, const Table &table, const Model &model);
    void step(double dt, Stats &stats, FrameLog &log) override;
    bool settle(double max_seconds, Stats &stats, FrameLog &log) override;
    void set_motion(int i, const Ball &state) override;
    void place_ball(int i, Point p) override;
    double now() const override { return epoch_ + world_now_; }

private:
    static void on_event(void *user, const c2d_world_event *event);
    void build();
    size_t add(size_t i);
    int overlapped(const Ball &b) const;
    void advance(double world_t, Stats &stats, FrameLog &log, bool record_paths);
    Ball state_of(size_t disk) const;
    void sample();
    bool moving() const;
    void impact(const c2d_world_event &e);
    void wall(const c2d_world_event &e);
    void record(double t, EventKind kind, int ball, int other, int feature, const Ball &b, double impulse);
    void waypoint(int ball, double t, const Ball &b);

    const Model model_;
    const Table table_;
    std::vector<uint64_t> memory_;  // the world's buffer (8-byte aligned)
    c2d_world *world_ = nullptr;
    std::vector<size_t> world_index_;  // ball -> disk, kNoDisk off the table
    std::vector<int> ball_of_;         // disk -> ball
    double epoch_ = 0, world_now_ = 0;
    // the advance in progress: where its records go
    Stats *stats_ = nullptr;
    FrameLog *log_ = nullptr;
    double frame_start_ = 0;  // world time
    bool record_paths_ = true;
};

WorldEngine::WorldEngine(const std::vector<Ball> &balls, const Table &table, const Model &model)
    : Engine(balls), model_(model), table_(table) {
    for (Ball &b : balls_) {
        b.wx = b.wy = b.wz = 0;
        b.motion = b.active ? (b.vx != 0 || b.vy != 0 ? Motion::Sliding : Motion::Stationary) : Motion::Pocketed;
    }
    build();
}

// A new world at time 0 holding every ball on the table as it is now.
void WorldEngine::build() {
    c2d_world_desc d{};
    d.capacity = balls_.size();
    d.width = table_.length;
    d.height = table_.width;
    d.boundary = C2D_WALLS;
    d.restitution = model_.ball.restitution;
    d.wall_restitution = model_.cushion.restitution;
    d.on_event = &WorldEngine::on_event;
    d.user = this;
    const size_t bytes = c2d_world_bytes(&d);
    memory_.assign(bytes / sizeof(uint64_t) + 1, 0);
    if (bytes == 0 || c2d_world_init(&world_, memory_.data(), memory_.size() * sizeof(uint64_t), &d) != C2D_OK)
        throw std::logic_error("world_engine: the world refused the table");
    epoch_ += world_now_;
    world_now_ = 0;
    world_index_.assign(balls_.size(), kNoDisk);
    ball_of_.clear();
    for (size_t i = 0; i < balls_.size(); ++i) {
        const Ball &b = balls_[i];
        if (!b.active) continue;
        world_index_[i] = add(i);
        ball_of_.push_back(static_cast<int>(i));
    }
}

// Ball i into the world.  Touching balls (a rack, the cradle's row) can be
// an ulp inside each other after rounding, which the world refuses: such a
// ball goes in where it just touches, moved out along the line of centres
// from the ball it overlaps by the least that does it.
size_t WorldEngine::add(size_t i) {
    Ball &b = balls_[i];
    for (int tries = 0; tries < 64; ++tries) {
        const c2d_body body{{b.x, b.y}, {b.vx, b.vy}, kBallMass};
        size_t disk;
        if (c2d_world_add(world_, &body, kBallRadius, &disk) == C2D_OK) return disk;
        const int other = overlapped(b);
        if (other < 0) break;
        const Ball &o = balls_[static_cast<size_t>(other)];
        const double dx = b.x - o.x, dy = b.y - o.y, d = std::hypot(dx, dy);
        if (!(d > kBallDiameter * (1 - 1e-12))) break;  // a real overlap, not rounding
        b.x = dx == 0 ? b.x : std::nextafter(b.x, dx > 0 ? INFINITY : -INFINITY);
        b.y = dy == 0 ? b.y : std::nextafter(b.y, dy > 0 ? INFINITY : -INFINITY);
    }
    throw std::logic_error("world_engine: the world refused ball " + std::to_string(b.number));
}

// A ball already in the world that b overlaps, or -1.
int WorldEngine::overlapped(const Ball &b) const {
    for (int k : ball_of_) {
        const Ball &o = balls_[static_cast<size_t>(k)];
        const double dx = o.x - b.x, dy = o.y - b.y;
        if (dx * dx + dy * dy < kBallDiameter * kBallDiameter) return k;
    }
    return -1;
}

void WorldEngine::on_event(void *user, const c2d_world_event *event) {
    WorldEngine &w = *static_cast<WorldEngine *>(user);
    if (event->kind == C2D_WORLD_IMPACT) w.impact(*event);
    else if (event->kind == C2D_WORLD_WALL) w.wall(*event);
}

Ball WorldEngine::state_of(size_t disk) const {
    c2d_body body;
    c2d_world_get(world_, disk, &body);
    Ball b = balls_[static_cast<size_t>(ball_of_[disk])];
    b.x = body.pos.x, b.y = body.pos.y, b.vx = body.vel.x, b.vy = body.vel.y;
    b.motion = b.vx != 0 || b.vy != 0 ? Motion::Sliding : Motion::Stationary;
    return b;
}

void WorldEngine::record(double t, EventKind kind, int ball, int other, int feature, const Ball &b, double impulse) {
    log_->events.push_back(Event{epoch_ + t, kind, ball, other, feature, b.x, b.y, b.vx, b.vy, 0, 0, 0, impulse});
}

void WorldEngine::waypoint(int ball, double t, const Ball &b) {
    if (record_paths_) log_->waypoints.push_back(Waypoint{ball, t - frame_start_, b.x, b.y, b.vx, b.vy, 0, 0});
}

void WorldEngine::impact(const c2d_world_event &e) {
    const int ia = ball_of_[e.a], ib = ball_of_[e.b];
    const Ball a = state_of(e.a), b = state_of(e.b);
    const double impulse = std::hypot(e.impulse.x, e.impulse.y);
    ++stats_->ball_ball_collisions;
    if (record_paths_) log_->contacts.push_back(pair_key(ia, ib));
    waypoint(ia, e.time, a);
    waypoint(ib, e.time, b);
    // one record for each ball, the lower-numbered first
    const bool a_first = a.number <= b.number;
    record(e.time, EventKind::BallBall, a_first ? ia : ib, a_first ? ib : ia, -1, a_first ? a : b, impulse);
    record(e.time, EventKind::BallBall, a_first ? ib : ia, a_first ? ia : ib, -1, a_first ? b : a, impulse);
}

void WorldEngine::wall(const c2d_world_event &e) {
    const int i = ball_of_[e.a];
    const Ball a = state_of(e.a);
    ++stats_->cushion_collisions;
    waypoint(i, e.time, a);
    record(e.time, EventKind::Cushion, i, -1, kCushionOfWall[e.b], a, std::hypot(e.impulse.x, e.impulse.y));
}

void WorldEngine::advance(double world_t, Stats &stats, FrameLog &log, bool record_paths) {
    stats_ = &stats, log_ = &log, frame_start_ = world_now_, record_paths_ = record_paths;
    c2d_world_advance(world_, world_t);
    world_now_ = world_t;
    stats_ = nullptr, log_ = nullptr;
    sample();
}

void WorldEngine::sample() {
    for (size_t disk = 0; disk < ball_of_.size(); ++disk) {
        Ball &b = balls_[static_cast<size_t>(ball_of_[disk])];
        if (b.active) b = state_of(disk);
    }
}

bool WorldEngine::moving() const {
    for (const Ball &b : balls_)
        if (b.active && (b.vx != 0 || b.vy != 0)) return true;
    return false;
}

void WorldEngine::step(double dt, Stats &stats, FrameLog &log) { advance(world_now_ + dt, stats, log, true); }

// Lossless balls never stop: once one moves, the run goes on to the end.
bool WorldEngine::settle(double max_seconds, Stats &stats, FrameLog &log) {
    if (!moving()) return true;
    advance(world_now_ + max_seconds, stats, log, false);
    return !moving();
}

void WorldEngine::set_motion(int i, const Ball &state) {
    const size_t k = static_cast<size_t>(i);
    if (!balls_[k].active) return;
    c2d_world_set_velocity(world_, world_index_[k], c2d_vec2{state.vx, state.vy});
    balls_[k] = state_of(world_index_[k]);
}

void WorldEngine::place_ball(int i, Point p) {
    Ball &b = balls_[static_cast<size_t>(i)];
    if (b.active) return;
    b = Ball{p.x, p.y, 0, 0, b.number, true};
    build();
}

}  // namespace

bool world_engine_runs(const Table &table, const Model &model) { return !model.friction && is_closed_box(table); }

std::unique_ptr<Engine> make_world_engine(const std::vector<Ball> &balls, const Table &table, const Model &model) {
    return std::unique_ptr<Engine>(new WorldEngine(balls, table, model));
}

}  // namespace demo
