// sim.cpp - see sim.h.
#include "sim.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "box2d_engine.h"
#include "checker.h"
#include "exact_engine.h"

extern "C" {
#include "collide2d.h"
}

namespace demo {

namespace {

constexpr double kStopSpeed = 0.01;            // m/s

}  // namespace

Simulation::Simulation(const SimConfig &config) : config_(config), frame_log_(new FrameLog) {
    Layout start = set_up(config.scene, config.gas_balls, config.seed);
    table_ = std::move(start.table);
    balls_initial_ = std::move(start.balls);
    if (config.response == Response::Box2d)
        engine_ = make_box2d_engine(balls_initial_, table_, config.losses.restitution);
    else
        engine_ = make_exact_engine(balls_initial_, table_, config.losses.restitution);
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

void Simulation::step() {
    const std::vector<Ball> before = engine_->balls_;
    frame_log_->contacts.clear();
    frame_log_->waypoints.clear();
    engine_->step(kFrameDt, stats_, *frame_log_);
    checker_.check_frame(before, engine_->balls_, *frame_log_, table_, kFrameDt, stats_);
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
