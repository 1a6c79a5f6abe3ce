/* SPDX-License-Identifier: MIT */
// scene.h - what is on the table at the start of a run.  SI units
// throughout (m, m/s, kg); x runs along the table, y across it.
//   break    a pool table (table.h: 2.54 m x 1.27 m, six pockets with jaws),
//            the cue ball on the head spot and 15 balls racked in a
//            triangle on the foot spot
//   elastic  the same table's rectangle and rack, without pockets
//   gas      a square box of disks on a jittered grid, 10% of its area
//            covered, with uniformly random velocity components (far from
//            equilibrium) and zero total momentum
//   cradle   the elastic table with a Newton's cradle: a row of touching
//            balls (1, 2, ...) along the centre line from the table's middle
//            towards the foot rail, the cue ball on the head spot in line
//            with it (cradle.h checks the outcome)
// --place puts chosen balls anywhere on the break or elastic table instead
// of the rack (only the placed balls are on the table).
#ifndef C2D_DEMO_SCENE_H
#define C2D_DEMO_SCENE_H

#include <cstdint>
#include <string>
#include <vector>

#include "pool/motion.h"
#include "pool/table.h"

namespace demo {

enum class Scene { Break, Elastic, Gas, Cradle };

// The longest cradle row: it fits between the table's middle and the foot
// rail with room for the last ball to leave.
constexpr int kMaxCradleBalls = 20;

// A ball put on the table by hand: number 0 (cue ball) to 15, centre (x, y).
struct Placement {
    int number;
    double x, y;
};

struct Setup {
    Table table;
    std::vector<Ball> balls;  // break and elastic: the cue ball first
};

// The break's rack is not tight: a real rack's balls are never all
// touching (the balls' diameters alone vary by +-0.127 mm, WPA's 2.25 in
// +- 0.005 in, and a rack leaves gaps).  The model is pooltool's
// (pooltool/layouts.py, EightBallRack: spacing_factor 1e-3): the triangle's
// pitch is 2 (R + kRackGap) and each ball is moved from its place by an
// offset uniform in the disk of radius kRackGap drawn from the seed, so
// neighbours are 0 to 4 kRackGap apart (2 kRackGap = 0.057 mm on average),
// never overlapping.  The elastic scene's rack stays tight (a Newton's
// cradle of the whole rack, energy compared with Box2D's).
constexpr double kRackGap = 1e-3 * kBallRadius;  // m

// The seed shuffles the rack (break, elastic) or places the gas.  With
// placements (break, elastic) only those balls are on the table, in the
// order given.  count: the gas's disks, or the cradle's row (1 to
// kMaxCradleBalls).
Setup set_up(Scene scene, const TableSpec &spec, int count, uint64_t seed,
             const std::vector<Placement> &placements = {});
// The 9-ball break: the cue ball on the head spot, balls 1-9 in a diamond
// behind the foot spot (the 1 at the apex, the 9 in the middle, 2-8
// shuffled by the seed), with the break rack's gaps (kRackGap).
Setup set_up_nine_ball(const TableSpec &spec, uint64_t seed);

// The table of the break (pockets) or elastic and cradle (a closed box) scene.
Table scene_table(Scene scene, const TableSpec &spec);

// Why placements cannot go on the table (a number outside 0..15 or given
// twice, a ball not wholly on the playing surface, two balls overlapping),
// or "" if they can.
std::string placement_error(const Table &table, const std::vector<Placement> &placements);

// Where a pocketed cue ball goes back: the head spot, or the nearest spot
// towards the head rail that no ball covers.
Point free_head_spot(const Table &table, const std::vector<Ball> &balls);

// Seeded, platform-independent generator (splitmix64), so scenes and runs
// are identical on every machine.
class Rng {
public:
    explicit Rng(uint64_t seed) : state_(seed) {}
    uint64_t next() {
        uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)

private:
    uint64_t state_;
};

}  // namespace demo

#endif
