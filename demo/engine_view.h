// engine_view.h - the one place where the window reads the simulation beyond
// balls(), table() and stats(): the table's shape with its pockets and jaws
// (what is drawn and what the aim line meets), each ball's angular velocity
// (rolling stripes), shots with a cue-tip offset, and the contacts of each
// frame (sounds).  Where the engine does not provide a quantity yet, this
// adapter derives it (demo/NEEDS_FROM_ENGINE.md says what, and what the
// engine is asked for); the engine's own fields are used as soon as they
// exist, detected at compile time by their names.
#ifndef C2D_DEMO_ENGINE_VIEW_H
#define C2D_DEMO_ENGINE_VIEW_H

#include <vector>

#include "scene.h"
#include "sim.h"

namespace demo {

struct Vec3 {
    double x, y, z;
};

// One side of a pocket's mouth: the straight jaw facing (the line a ball's
// surface touches, a at the nose, n into the mouth) and the rounded nose.
struct JawShape {
    Segment facing;
    double nose_x, nose_y, nose_r;
};

struct PocketShape {
    double x, y;
    double radius;  // a ball whose centre comes closer than this falls
    JawShape jaws[2];
};

struct TableShape {
    double length, width;  // playing surface [0, length] x [0, width]
    double rail;           // drawn rail, cushion included, beyond the surface
    double cushion;        // rubber between the cushion face and the wood
    std::vector<Segment> cushions;
    std::vector<PocketShape> pockets;
};

TableShape table_shape(const Table &table);

// rad/s, world frame (z up).
Vec3 angular_velocity(const Ball &ball);

// A shot with the cue tip offset (fractions of R, |offset| <= 0.5); the
// offset is dropped while the engine's Shot has no room for it.
Shot make_shot(double angle_deg, double speed, double side, double topback);
bool shots_take_spin();

// What made a sound in a frame.
enum class ContactKind { BallBall, Cushion, Pocket };
struct Contact {
    ContactKind kind;
    double x, y;     // where, m
    double impulse;  // N s (a fall: the ball's momentum)
};

// Reads the contacts of each frame: call before() ahead of Simulation::step()
// and after() behind it.
class ContactListener {
public:
    void before(const Simulation &sim);
    std::vector<Contact> after(const Simulation &sim);

private:
    std::vector<Ball> balls_;
    long ball_ball_ = 0, cushion_ = 0;
    bool primed_ = false;
};

}  // namespace demo

#endif
