// sim.h - a run of the demo, without SDL: its configuration (scene, engine,
// losses); the Simulation, which sets up the scene, steps the engine frame
// by frame, has the checker check every frame, and applies rolling
// resistance between frames (each moving ball's speed drops by
// rolling_deceleration * kFrameDt; below 1 cm/s it stops); and the one main
// loop that the window and the headless runs share.  State is in double, SI
// units (m, m/s, kg, s).
#ifndef C2D_DEMO_SIM_H
#define C2D_DEMO_SIM_H

#include <cstdint>
#include <memory>
#include <vector>

#include "checker.h"
#include "engine.h"
#include "scene.h"

namespace demo {

enum class Response { Collide2d, Box2d };

struct Shot {
    double angle_deg;  // 0 = towards the foot rail (+x), counter-clockwise
    double speed;      // m/s
};

// What a scene loses.  The break plays like a real table; the elastic and
// gas scenes lose nothing, so their kinetic energy checks the engine.
struct Losses {
    Restitution restitution;
    double rolling_deceleration;  // m/s^2, applied between frames; 0: none
    bool none() const { return restitution.ball == 1 && restitution.cushion == 1 && rolling_deceleration == 0; }
};
constexpr Losses kTableLosses = {{0.95, 0.8}, 0.15};  // rolling resistance ~0.015 g
constexpr Losses kNoLosses = {{1.0, 1.0}, 0.0};

struct SimConfig {
    Scene scene = Scene::Break;
    Response response = Response::Collide2d;
    int gas_balls = 1000;
    uint64_t seed = 1;
    Losses losses = kTableLosses;
    // The scene with the losses that go with it.
    void set_scene(Scene s) {
        scene = s;
        losses = s == Scene::Break ? kTableLosses : kNoLosses;
    }
};

constexpr double kMaxShotSpeed = 15.0;  // Box2D moves at most 2 units/step: 15 m/s at our scale

class Simulation {
public:
    explicit Simulation(const SimConfig &config);
    ~Simulation();
    Simulation(const Simulation &) = delete;
    Simulation &operator=(const Simulation &) = delete;
    Simulation(Simulation &&) noexcept;
    Simulation &operator=(Simulation &&) noexcept;  // the window's re-rack

    // Strikes the cue ball (break scenes; ignored if it is off the table).
    void shoot(const Shot &shot);
    // Advances one frame of kFrameDt.
    void step();
    // All balls at rest (never true in the lossless scenes once moving).
    bool at_rest() const;
    bool cue_on_table() const;
    // Puts a pocketed cue ball back on the head spot (or the nearest free spot).
    void respot_cue();

    const SimConfig &config() const { return config_; }
    const Table &table() const { return table_; }
    const std::vector<Ball> &balls() const;
    const Stats &stats() const { return stats_; }
    int balls_total() const { return static_cast<int>(balls().size()); }
    int object_balls_left() const;
    double energy() const;
    void momentum(double out[2]) const;
    bool lossless() const { return config_.losses.none(); }

private:
    void apply_rolling_resistance();

    SimConfig config_;
    Table table_;
    std::unique_ptr<Engine> engine_;
    FrameLog frame_log_;
    Stats stats_;
    Checker checker_;
};

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
};

// The main loop of the window and of headless runs: frame by frame until the
// driver ends it; whenever the table is at rest, a pocketed cue ball goes
// back on the head spot.
void run(Simulation &sim, Driver &driver);

}  // namespace demo

#endif
