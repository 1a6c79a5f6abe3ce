/* SPDX-License-Identifier: MIT */
// sim.h - a run of the demo, without SDL: its configuration (scene, engine,
// every physical parameter), the Simulation, which sets up the scene, steps
// the engine frame by frame and has the checker check every frame; the one
// main loop that the window and the headless runs share; and the shot seam
// (simulate_shot) through which rules and a computer opponent play a shot
// with the same engine.  State is in double, SI units (m, m/s, kg, s, rad).
#ifndef C2D_DEMO_SIM_H
#define C2D_DEMO_SIM_H

#include <cstdint>
#include <memory>
#include <vector>

#include "pool/checker.h"
#include "pool/engine.h"
#include "pool/events.h"
#include "pool/model.h"
#include "pool/scene.h"
#include "pool/world_engine.h"

namespace demo {

enum class Response { Collide2d, Box2d };

struct Shot {
    double angle_deg;    // 0 = towards the foot rail (+x), counter-clockwise
    double speed;        // m/s: the cue ball's speed just after the strike
    double side = 0;     // tip right (+, right english) or left (-) of centre, fraction of R
    double topback = 0;  // tip above (+, follow) or below (-, draw) centre, fraction of R
    double elevation = 0;  // the cue's elevation above the cloth, degrees in [0, kMaxElevation]
};

// A cue raised further than this hits the ball almost straight down (a
// masse's 80-85 degrees is the steepest players use).
constexpr double kMaxElevation = 85.0;

// Further off centre than about half a radius a chalked tip slips off the
// ball (a miscue; Alciatore's measurements put the limit near 0.5 R).
constexpr double kMaxTipOffset = 0.5;
constexpr double kMaxShotSpeed = 15.0;  // Box2D moves at most 2 units/step: 15 m/s at our scale

// The pool scene's physics (motion.h, model.h).  Values and why:
//   g        9.81 m/s^2
//   mu_s     0.2     ball-cloth sliding friction; Alciatore's typical value
//                    (measured 0.15-0.4)
//   mu_r     0.01    rolling resistance (Alciatore 0.005-0.015)
//   mu_sp    0.0127  spinning friction: wz decays at 5 mu_sp g / (2R) =
//                    10.9 rad/s^2, the middle of the 5-15 rad/s^2 Alciatore
//                    measured (and pooltool's default, 0.444 R); a coefficient
//                    of 0.044 would give 37.8 rad/s^2, a sidespin
//                    that dies in a third of the time
//   ball     e 0.95 (measured 0.92-0.98), mu 0.05 (0.03-0.08), beta 0: the
//                    contact points stop relative to each other when the
//                    impulse sticks (pooltool's frictional-inelastic model);
//                    ContactModel::SphereAlciatore: mu(v) of the sliding speed
//                    instead (sphere_contact.h)
//   cushion  e 0.8 (measured 0.6-0.9), mu 0.2, beta 0; the nose 0.64 D =
//                    1.28 R above the cloth (Mathavan et al. 2010 give
//                    0.635 D for a standard table; 0.64 D is the figure of
//                    the pooltool runs of issue 21, kept for like-for-like
//                    comparison; docs/POOL.md)
//   contacts approaching slower than 5 mm/s are absorbed (model.h)
// Impacts are between spheres (ContactModel::Sphere, sphere_contact.h): the
// full 3-D slip sees friction, and the cushion touches the ball above its
// centre.  ContactModel::Disk keeps the former disks in the plane of the centres
// for comparison (only the horizontal slip, R wz included, sees friction).
constexpr Model kPoolModel = {true, {9.81, 0.2, 0.01, 0.0127}, {0.95, 0.05, 0.0}, {0.8, 0.2, 0.0}, 0.005};
// The elastic, gas and cradle scenes: no losses at all, so kinetic energy checks
// the engine.
constexpr Model kFrictionless = {false, {9.81, 0, 0, 0}, {1.0, 0, -1.0}, {1.0, 0, -1.0}, 0};

// Every parameter of a run; the one place physical parameters are set.
struct SimConfig {
    Scene scene = Scene::Break;
    Response response = Response::Collide2d;
    int gas_balls = 1000;
    int cradle_balls = 5;                // the cradle's row
    uint64_t seed = 1;
    Model model = kPoolModel;
    TableSpec table;                     // table.h: size and pocket geometry
    std::vector<Placement> placements;   // break, elastic: only these balls
    CheckMode check = CheckMode::Full;   // how much of each frame the checker checks (checker.h)
    // who finds the world's candidates in the pool scenes (break, elastic,
    // 8-ball; the gas and the cradle use the world's cells): world_engine.h
    WorldBroadphase broadphase = WorldBroadphase::Tree;
    // The scene with the physics that goes with it.
    // (The contact model and the cue's end mass chosen are kept: the one only
    // matters with friction, the other is the cue's, not the scene's.)
    void set_scene(Scene s) {
        scene = s;
        const ContactModel contact = model.contact;
        const double end_mass = model.cue_end_mass;
        model = s == Scene::Break ? kPoolModel : kFrictionless;
        model.contact = contact;
        model.cue_end_mass = end_mass;
    }
};

class Simulation {
public:
    explicit Simulation(const SimConfig &config);
    ~Simulation();
    Simulation(const Simulation &) = delete;
    Simulation &operator=(const Simulation &) = delete;
    Simulation(Simulation &&) noexcept;
    Simulation &operator=(Simulation &&) noexcept;  // the window's re-rack

    // Strikes the cue ball (break scenes; ignored if it is off the table).
    // From a table at rest the engine restarts at time 0 first (set_balls),
    // so a shot gives the bits simulate_shot gives from the same table.
    void shoot(const Shot &shot);
    // Advances one frame of kFrameDt.
    void step();
    // Every ball stopped: no translation and no spin (never true in the
    // lossless scenes once moving).
    bool at_rest() const;
    bool cue_on_table() const;
    // Puts a pocketed cue ball back on the head spot (or the nearest free spot).
    void respot_cue();
    // New places for the balls of a table at rest (the same balls in the same
    // order, each at rest or pocketed): ball in hand, a re-spotted 8.
    void set_balls(const std::vector<Ball> &balls);

    const SimConfig &config() const { return config_; }
    const Table &table() const { return table_; }
    // Each ball's state at the end of the last frame: position, velocity,
    // angular velocity (rad/s, world frame, z up), motion state.
    const std::vector<Ball> &balls() const;
    const Stats &stats() const { return stats_; }
    // What happened in the last step(), in time order; a shot's strike comes
    // in the step after shoot().
    const std::vector<Event> &frame_events() const { return frame_events_; }
    double time() const;  // simulated seconds
    int balls_total() const { return static_cast<int>(balls().size()); }
    int object_balls_left() const;
    double energy() const;  // J, rotation included
    void momentum(double out[2]) const;
    bool lossless() const { return !config_.model.friction; }

private:
    SimConfig config_;
    Table table_;
    std::unique_ptr<Engine> engine_;
    FrameLog frame_log_;
    std::vector<Event> frame_events_, strikes_;
    std::vector<Ball> before_;  // the balls at the frame's start, for the checker
    Stats stats_;
    Checker checker_;
};

// A shot played from a given table state to rest, without frames, checker
// or SDL: for game rules and a computer opponent weighing candidate shots
// with the same engine.  The cue ball is the ball numbered 0.
struct ShotOutcome {
    std::vector<Event> events;  // in time order; the strike first
    std::vector<Ball> balls;    // at rest; pocketed balls are inactive, where they fell
    Stats stats;                // collisions, pocketed (object balls), scratches
    double seconds;             // from the strike until the last ball stopped
    bool settled;               // false: not at rest after an hour, or the event budget ran out
    bool stopped = false;       // ended early by the caller's question (not settled either)
};
ShotOutcome simulate_shot(const SimConfig &config, const std::vector<Ball> &balls, const Shot &shot);
// The same, ending early once stop (asked every Engine::kStopStretch
// simulated seconds with the events so far, the strike first) says so.
ShotOutcome simulate_shot(const SimConfig &config, const std::vector<Ball> &balls, const Shot &shot,
                          const Engine::StopWhen &stop);
// The same from a table already in motion (balls with velocities and spins;
// each ball's motion state is worked out from them), without a strike.
ShotOutcome simulate_to_rest(const SimConfig &config, const std::vector<Ball> &balls);

// What makes a run of the one main loop (run) a window game or a headless
// run: where shots and the end come from, and what becomes of each frame.
class Driver {
public:
    virtual ~Driver() = default;
    // Start of a frame: false ends the run.  May shoot or re-rack.
    virtual bool next_frame(Simulation &sim) = 0;
    // The cue ball is back on the table if the table was at rest; false ends
    // the run.
    virtual bool before_step(Simulation &sim, bool was_at_rest) = 0;
    // The frame has been simulated.
    virtual void after_step(const Simulation &sim) = 0;
    // Real seconds each frame takes (the loop waits for the clock); 0: as
    // fast as it goes.  The window runs in real time.
    virtual double frame_seconds() const { return kFrameDt; }
};

// The main loop of the window and of headless runs: frame by frame until the
// driver ends it; whenever the table is at rest, a pocketed cue ball goes
// back on the head spot.  Frames of kFrameDt simulated seconds are paced by
// the steady clock at driver.frame_seconds() each, counted from the start
// (no drift); a loop that falls more than a quarter second behind starts
// counting again rather than rush.  Built with emscripten, the loop is the
// browser's animation frames (the frames due by the clock, at most 4 a
// callback) and run does not return: the caller's objects live on with the
// page (demo/web, docs/WEB.md).
void run(Simulation &sim, Driver &driver);

}  // namespace demo

#endif
