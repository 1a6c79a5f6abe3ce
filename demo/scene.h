// scene.h - what is on the table at the start of a run: the table's
// geometry (cushions, pockets) and the balls of each scene.  SI units
// throughout (m, m/s, kg); x runs along the table, y across it.
//   break    a pool table (2.54 m x 1.27 m, six pockets), the cue ball on the
//            head spot and 15 balls racked in a triangle on the foot spot
//   elastic  the same table and rack without pockets
//   gas      a square box of disks on a jittered grid, 10% of its area
//            covered, with uniformly random velocity components (far from
//            equilibrium) and zero total momentum
#ifndef C2D_DEMO_SCENE_H
#define C2D_DEMO_SCENE_H

#include <cstdint>
#include <vector>

namespace demo {

enum class Scene { Break, Elastic, Gas };

constexpr double kBallDiameter = 0.05715;
constexpr double kBallRadius = kBallDiameter / 2;
constexpr double kBallMass = 0.17;

struct Ball {
    double x, y, vx, vy;
    int number;  // 0 = cue ball, 1..15 object balls; gas: index
    bool active;
};

struct Segment { double ax, ay, bx, by, nx, ny; };  // cushion face, n points into the table
struct Pocket { double x, y, capture_radius, draw_radius; };

struct Table {
    double length, width;   // playing surface [0,length] x [0,width]
    double rail;            // drawn rail width
    std::vector<Segment> cushions;
    std::vector<Pocket> pockets;
};

struct Layout {
    Table table;
    std::vector<Ball> balls;  // break and elastic: the cue ball first
};

// The seed shuffles the rack (break, elastic) or places the gas.
Layout set_up(Scene scene, int gas_balls, uint64_t seed);

struct Point { double x, y; };

// Where a pocketed cue ball goes back: the head spot, or the nearest spot
// towards the head rail that no ball covers.
Point free_head_spot(const Table &table, const std::vector<Ball> &balls);

}  // namespace demo

#endif
