/* SPDX-License-Identifier: MIT */
// engine.h - what the simulation asks of an engine: move the balls on by a
// frame, resolving the impacts on the way, and report what it resolved, so
// the checker can tell a resolved contact from a tunnelled pair.  Two
// engines: the library's event-driven world (world_engine.h) and Box2D's
// own solver (box2d_engine.h).
#ifndef C2D_DEMO_ENGINE_H
#define C2D_DEMO_ENGINE_H

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "pool/events.h"
#include "pool/model.h"
#include "pool/scene.h"

namespace demo {

constexpr double kFrameDt = 1.0 / 60.0;

// Box2D is tuned for bodies of 0.1-10 units and moves a body at most
// b2_maxTranslation (2 units) per step: 8 units per metre makes a ball 0.46
// units and keeps 15 m/s under that limit at 60 frames/s.  A power of two, so
// converting to and from Box2D units is exact.
constexpr double kUnitsPerMetre = 8.0;

struct Stats {
    long steps = 0;
    double sim_seconds = 0;
    long ball_ball_collisions = 0;
    long cushion_collisions = 0;  // rails and jaws
    int pocketed = 0;             // object balls
    int scratches = 0;            // the cue ball pocketed
    int escaped = 0;
    long tunnelled = 0;
    double max_overlap = 0;       // fraction of a diameter
    long event_cap_frames = 0;    // frames whose event budget ran out
    long checked_pairs = 0;       // pairs the checker looked at (checker.h)
    double max_energy_step = 0;   // the checker's largest relative energy change between frames
};

// Where a ball's motion changes inside a frame, and the motion from there on:
// p(t) = (x, y) + (vx, vy) (t - t0) + (ax, ay) (t - t0)^2 / 2 until the
// ball's next waypoint.  Before its first waypoint a ball moves straight
// from where it was at the frame's start.
struct Waypoint {
    int ball;
    double t, x, y, vx, vy, ax, ay;
    bool operator<(const Waypoint &o) const { return ball != o.ball ? ball < o.ball : t < o.t; }
};

// An unordered pair of balls as one sortable number.
inline uint64_t pair_key(int i, int j) {
    if (i > j) std::swap(i, j);
    return (static_cast<uint64_t>(i) << 32) | static_cast<uint32_t>(j);
}

struct FrameLog {
    std::vector<uint64_t> contacts;    // pair_key of the pairs resolved this frame
    std::vector<Waypoint> waypoints;   // the world engine only: Box2D moves straight per step
    std::vector<Event> events;         // in time order
};

// The balls are the engine's state: the simulation reads them, and changes
// them only through set_motion and place_ball, so an engine learns exactly
// which balls changed and keeps what it knows of the others.
class Engine {
public:
    virtual ~Engine() = default;
    // Moves every ball on by dt, resolving the impacts on the way: counts
    // them in stats, records them in log (which the caller has emptied).
    virtual void step(double dt, Stats &stats, FrameLog &log) = 0;
    // Runs on, without frames, until every ball is at rest or pocketed or
    // max_seconds have passed; only log.events is filled.  Returns whether
    // the balls came to rest.
    virtual bool settle(double max_seconds, Stats &stats, FrameLog &log) = 0;
    // New velocities for a ball on the table (a shot), from now on; ignored
    // for a pocketed ball.  An engine without spin keeps only vx, vy.
    virtual void set_motion(int i, const Ball &state) = 0;
    // A pocketed ball back on the table, at rest at p; ignored for a ball
    // still on the table.
    virtual void place_ball(int i, Point p) = 0;
    // The simulated time, s.
    virtual double now() const = 0;
    const std::vector<Ball> &balls() const { return balls_; }
    // A question settle asks between stretches of the run (kStopStretch
    // simulated seconds each) with log.events so far: true ends the run
    // there, not at rest (settle returns false).  For a caller that knows
    // early that it has seen enough (the opponent, of a shot that fouls);
    // the stretches change nothing else (the world's frame independence).
    // The world engine asks it; Box2D's ignores it.
    using StopWhen = std::function<bool(const std::vector<Event> &)>;
    static constexpr double kStopStretch = 0.25;
    void stop_when(StopWhen stop) { stop_ = std::move(stop); }

protected:
    explicit Engine(const std::vector<Ball> &balls) : balls_(balls) {}
    std::vector<Ball> balls_;
    StopWhen stop_;
};

}  // namespace demo

#endif
