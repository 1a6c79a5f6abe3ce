// sim.cpp - see sim.h.
#include "sim.h"

#include <cmath>

#include "box2d_engine.h"
#include "exact_engine.h"

namespace demo {

namespace {

// Below it a ball stops rather than crawl; and a last frame's slowing can
// never reverse a ball.
constexpr double kStopSpeed = 0.01;  // m/s

}  // namespace

Simulation::Simulation(const SimConfig &config) : config_(config) {
    const Layout start = set_up(config.scene, config.gas_balls, config.seed);
    table_ = start.table;
    if (config.response == Response::Box2d)
        engine_ = make_box2d_engine(start.balls, table_, config.losses.restitution);
    else
        engine_ = make_exact_engine(start.balls, table_, config.losses.restitution);
}

Simulation::~Simulation() = default;
Simulation::Simulation(Simulation &&) noexcept = default;
Simulation &Simulation::operator=(Simulation &&) noexcept = default;

const std::vector<Ball> &Simulation::balls() const { return engine_->balls(); }

bool Simulation::cue_on_table() const {
    return config_.scene != Scene::Gas && balls()[0].active;
}

void Simulation::shoot(const Shot &shot) {
    if (!cue_on_table()) return;
    const double a = shot.angle_deg * (M_PI / 180.0);
    engine_->set_velocity(0, shot.speed * std::cos(a), shot.speed * std::sin(a));
}

bool Simulation::at_rest() const {
    for (const Ball &b : balls())
        if (b.active && (b.vx != 0 || b.vy != 0)) return false;
    return true;
}

int Simulation::object_balls_left() const {
    int left = 0;
    for (const Ball &b : balls()) left += b.active && b.number != 0;
    return left;
}

void Simulation::respot_cue() {
    if (config_.scene == Scene::Gas || balls()[0].active) return;
    engine_->place_ball(0, free_head_spot(table_, balls()));
}

double Simulation::energy() const {
    double e = 0;
    for (const Ball &b : balls())
        if (b.active) e += 0.5 * kBallMass * (b.vx * b.vx + b.vy * b.vy);
    return e;
}

void Simulation::momentum(double out[2]) const {
    out[0] = out[1] = 0;
    for (const Ball &b : balls())
        if (b.active) {
            out[0] += kBallMass * b.vx;
            out[1] += kBallMass * b.vy;
        }
}

// Rolling resistance changes velocities only between frames, so the motion
// inside a frame stays straight and its impacts exact.
void Simulation::apply_rolling_resistance() {
    const double slowing = config_.losses.rolling_deceleration * kFrameDt;
    for (size_t i = 0; i < balls().size(); ++i) {
        const Ball &b = balls()[i];
        const double speed = std::hypot(b.vx, b.vy);
        if (!b.active || speed == 0) continue;
        const double slower = speed - slowing;
        const double scale = slower < kStopSpeed ? 0.0 : slower / speed;
        engine_->set_velocity(static_cast<int>(i), b.vx * scale, b.vy * scale);
    }
}

void Simulation::step() {
    const std::vector<Ball> before = balls();
    frame_log_.contacts.clear();
    frame_log_.waypoints.clear();
    engine_->step(kFrameDt, stats_, frame_log_);
    checker_.check_frame(before, balls(), frame_log_, table_, kFrameDt, stats_);
    if (config_.losses.rolling_deceleration > 0) apply_rolling_resistance();
    ++stats_.steps;
    stats_.sim_seconds = static_cast<double>(stats_.steps) * kFrameDt;
}

void run(Simulation &sim, Driver &driver) {
    while (driver.next_frame(sim)) {
        const bool at_rest = sim.at_rest();
        if (at_rest) sim.respot_cue();
        if (!driver.before_step(sim, at_rest)) return;
        sim.step();
        driver.after_step(sim);
    }
}

}  // namespace demo
