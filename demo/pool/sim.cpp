/* SPDX-License-Identifier: MIT */
// sim.cpp - see sim.h.
#include "pool/sim.h"

#include <chrono>
#include <cmath>
#include <thread>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

#include "pool/box2d_engine.h"
#include "pool/world_engine.h"

namespace demo {

namespace {

std::unique_ptr<Engine> make_engine(const SimConfig &config, const std::vector<Ball> &balls, const Table &table) {
    if (config.response == Response::Box2d) return make_box2d_engine(balls, table, config.model);
    // the pool scenes' candidates from Box2D's tree; the gas's and the
    // cradle's from the world's cells (100,000 disks: the cells are faster)
    const bool pool = config.scene != Scene::Gas && config.scene != Scene::Cradle;
    return make_world_engine(balls, table, config.model, pool ? config.broadphase : WorldBroadphase::Cells);
}

// The cue ball's index, or -1.
int cue_index(const std::vector<Ball> &balls) {
    for (size_t i = 0; i < balls.size(); ++i)
        if (balls[i].number == 0) return static_cast<int>(i);
    return -1;
}

// The strike with the model's cue, and its event.
Event strike_cue(Engine &engine, int cue, const Shot &shot, const Model &model) {
    const Ball b = strike(engine.balls()[static_cast<size_t>(cue)], shot.angle_deg * (M_PI / 180.0), shot.speed,
                          shot.side, shot.topback, shot.elevation * (M_PI / 180.0), model.cue_end_mass);
    engine.set_motion(cue, b);
    return Event{engine.now(), EventKind::Strike, cue, -1, -1, b.x, b.y, b.vx, b.vy, b.wx, b.wy, b.wz,
                 kBallMass * shot.speed};
}

}  // namespace

Simulation::Simulation(const SimConfig &config)
    : config_(config), checker_(config.check, config.seed, !config.model.friction) {
    const int count = config.scene == Scene::Cradle ? config.cradle_balls : config.gas_balls;
    const Setup start = set_up(config.scene, config.table, count, config.seed, config.placements);
    table_ = start.table;
    engine_ = make_engine(config, start.balls, table_);
}

Simulation::~Simulation() = default;
Simulation::Simulation(Simulation &&) noexcept = default;
Simulation &Simulation::operator=(Simulation &&) noexcept = default;

const std::vector<Ball> &Simulation::balls() const { return engine_->balls(); }

double Simulation::time() const { return engine_->now(); }

bool Simulation::cue_on_table() const {
    const int cue = cue_index(balls());
    return config_.scene != Scene::Gas && cue >= 0 && balls()[static_cast<size_t>(cue)].active;
}

void Simulation::shoot(const Shot &shot) {
    if (!cue_on_table()) return;
    // From a table at rest the engine starts afresh at time 0, as
    // simulate_shot's does: the world's clock then reads the same at every
    // event, so the window's game, frame by frame, is the headless game bit
    // for bit (test_game: window_plays_the_headless_game).
    if (at_rest()) set_balls(balls());
    strikes_.push_back(strike_cue(*engine_, cue_index(balls()), shot, config_.model));
}

bool Simulation::at_rest() const {
    for (const Ball &b : balls())
        if (b.active && (b.vx != 0 || b.vy != 0 || b.wx != 0 || b.wy != 0 || b.wz != 0)) return false;
    return true;
}

int Simulation::object_balls_left() const {
    int left = 0;
    for (const Ball &b : balls()) left += b.active && b.number != 0;
    return left;
}

void Simulation::respot_cue() {
    const int cue = cue_index(balls());
    if (config_.scene == Scene::Gas || cue < 0 || balls()[static_cast<size_t>(cue)].active) return;
    engine_->place_ball(cue, free_head_spot(table_, balls()));
}

void Simulation::set_balls(const std::vector<Ball> &balls) { engine_ = make_engine(config_, balls, table_); }

double Simulation::energy() const {
    double e = 0;
    for (const Ball &b : balls()) e += demo::energy(b);
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

void Simulation::step() {
    const bool checked = checker_.mode() != CheckMode::Off;
    if (checked) before_ = balls();
    frame_log_.contacts.clear();
    frame_log_.waypoints.clear();
    frame_log_.events.clear();
    engine_->step(kFrameDt, stats_, frame_log_);
    if (checked) checker_.check_frame(before_, balls(), frame_log_, table_, kFrameDt, stats_);
    frame_events_.swap(strikes_);
    strikes_.clear();
    frame_events_.insert(frame_events_.end(), frame_log_.events.begin(), frame_log_.events.end());
    ++stats_.steps;
    stats_.sim_seconds = static_cast<double>(stats_.steps) * kFrameDt;
}

namespace {

ShotOutcome play(const SimConfig &config, const std::vector<Ball> &balls, const Shot *shot,
                 const Engine::StopWhen *stop) {
    const Table table = scene_table(config.scene, config.table);
    std::unique_ptr<Engine> engine = make_engine(config, balls, table);
    ShotOutcome out{};
    FrameLog log;
    const int cue = cue_index(balls);
    if (shot && cue >= 0 && balls[static_cast<size_t>(cue)].active)
        log.events.push_back(strike_cue(*engine, cue, *shot, config.model));
    if (stop) engine->stop_when(*stop);
    const double start = engine->now();
    out.settled = engine->settle(3600, out.stats, log);
    out.stopped = !out.settled && stop && engine->now() - start < 3600;
    out.events = std::move(log.events);
    out.balls = engine->balls();
    out.seconds = engine->now() - start;
    return out;
}

}  // namespace

ShotOutcome simulate_shot(const SimConfig &config, const std::vector<Ball> &balls, const Shot &shot) {
    return play(config, balls, &shot, nullptr);
}

ShotOutcome simulate_shot(const SimConfig &config, const std::vector<Ball> &balls, const Shot &shot,
                          const Engine::StopWhen &stop) {
    return play(config, balls, &shot, &stop);
}

ShotOutcome simulate_to_rest(const SimConfig &config, const std::vector<Ball> &balls) {
    return play(config, balls, nullptr, nullptr);
}

namespace {

// One frame of the loop: false once the driver ends the run.
bool run_frame(Simulation &sim, Driver &driver) {
    if (!driver.next_frame(sim)) return false;
    const bool at_rest = sim.at_rest();
    if (at_rest) sim.respot_cue();
    if (!driver.before_step(sim, at_rest)) return false;
    sim.step();
    driver.after_step(sim);
    return true;
}

#ifdef __EMSCRIPTEN__
// The browser's loop: called at each animation frame, it runs the frames
// due by the clock since the start (no drift, at most 4 at once; a quarter
// second behind, it counts afresh, as the native loop does).  A driver that
// ends the run stops the loop; the page stays as it was.
struct BrowserLoop {
    Simulation *sim;
    Driver *driver;
    double origin_ms;
    long paced;
};

void browser_frame(void *arg) {
    BrowserLoop &loop = *static_cast<BrowserLoop *>(arg);
    const double pace = loop.driver->frame_seconds();
    const double now = emscripten_get_now();
    long due = pace > 0 ? static_cast<long>((now - loop.origin_ms) / (1000 * pace)) : loop.paced + 1;
    if (due - loop.paced > 15) {  // a quarter second behind (a hidden tab): start counting again
        loop.origin_ms = now - 1000 * pace;
        loop.paced = 0;
        due = 1;
    }
    for (int n = 0; loop.paced < due && n < 4; ++n, ++loop.paced)
        if (!run_frame(*loop.sim, *loop.driver)) {
            emscripten_cancel_main_loop();
            return;
        }
}
#endif

}  // namespace

void run(Simulation &sim, Driver &driver) {
#ifdef __EMSCRIPTEN__
    // The browser cannot block: the loop becomes its animation frames, and
    // this call does not return (the caller's objects live on with the page).
    static BrowserLoop loop;
    loop = BrowserLoop{&sim, &driver, emscripten_get_now(), 0};
    emscripten_set_main_loop_arg(browser_frame, &loop, 0, 1);
#else
    using Clock = std::chrono::steady_clock;
    Clock::time_point origin = Clock::now();
    long paced = 0;
    while (run_frame(sim, driver)) {
        const double pace = driver.frame_seconds();
        if (pace <= 0) continue;
        const Clock::time_point due = origin + std::chrono::duration_cast<Clock::duration>(
                                                   std::chrono::duration<double>(pace * static_cast<double>(++paced)));
        const Clock::time_point now = Clock::now();
        if (now < due) {
            std::this_thread::sleep_until(due);
        } else if (now - due > std::chrono::milliseconds(250)) {
            origin = now;
            paced = 0;
        }
    }
#endif
}

}  // namespace demo
