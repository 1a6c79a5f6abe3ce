// scene.cpp - see scene.h.  The rack's rows are sqrt(3) radii apart (balls
// touching in a triangle); the gas box's side s holds N disks of radius r at
// area fraction f: N pi r^2 = f s^2.
#include "scene.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace demo {

namespace {

constexpr double kTableLength = 2.54;
constexpr double kTableWidth = 1.27;
constexpr double kCornerMouth = 0.08;   // cushion nose to the corner, along each rail
constexpr double kSideMouth = 0.065;    // half-width of a side pocket opening
constexpr double kGasAreaFraction = 0.1;

// Seeded, platform-independent generator (splitmix64), so scenes and runs are
// identical on every machine.
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

Segment make_segment(double ax, double ay, double bx, double by, double nx, double ny) {
    return Segment{ax, ay, bx, by, nx, ny};
}

void add_rectangle_cushions(Table &t) {
    const double L = t.length, W = t.width;
    t.cushions.push_back(make_segment(0, 0, L, 0, 0, 1));
    t.cushions.push_back(make_segment(0, W, L, W, 0, -1));
    t.cushions.push_back(make_segment(0, 0, 0, W, 1, 0));
    t.cushions.push_back(make_segment(L, 0, L, W, -1, 0));
}

void add_pocketed_cushions(Table &t) {
    const double L = t.length, W = t.width, m = kCornerMouth, g = kSideMouth;
    for (double y : {0.0, W}) {
        const double ny = y == 0.0 ? 1.0 : -1.0;
        t.cushions.push_back(make_segment(m, y, L / 2 - g, y, 0, ny));
        t.cushions.push_back(make_segment(L / 2 + g, y, L - m, y, 0, ny));
    }
    t.cushions.push_back(make_segment(0, m, 0, W - m, 1, 0));
    t.cushions.push_back(make_segment(L, m, L, W - m, -1, 0));
    // A capture radius of at least the mouth width means a ball crossing a
    // rail line through an opening is already inside the pocket's circle.
    for (double x : {0.0, L})
        for (double y : {0.0, W}) t.pockets.push_back(Pocket{x, y, m, 0.062});
    for (double y : {0.0, W}) t.pockets.push_back(Pocket{L / 2, y, g, 0.066});
}

Ball make_ball(double x, double y, int number) { return Ball{x, y, 0, 0, number, true}; }

double head_spot_x(const Table &t) { return 0.25 * t.length; }
double centre_line_y(const Table &t) { return 0.5 * t.width; }

// 15 balls in a triangle behind the foot spot, touching: the 1 at the apex,
// the 8 in the middle of the third row, the others shuffled by the seed.
void rack(std::vector<Ball> &balls, const Table &t, uint64_t seed) {
    std::vector<int> order = {2, 3, 4, 5, 6, 7, 9, 10, 11, 12, 13, 14, 15};
    Rng rng(seed);
    for (size_t i = order.size() - 1; i > 0; --i)
        std::swap(order[i], order[static_cast<size_t>(rng.next() % (i + 1))]);
    const double apex_x = 0.75 * t.length, cy = centre_line_y(t);
    const double row_step = kBallRadius * std::sqrt(3.0);
    size_t next = 0;
    for (int row = 0; row < 5; ++row) {
        for (int k = 0; k <= row; ++k) {
            int number;
            if (row == 0) number = 1;
            else if (row == 2 && k == 1) number = 8;
            else number = order[next++];
            balls.push_back(make_ball(apex_x + row * row_step,
                                      cy + (k - 0.5 * row) * kBallDiameter, number));
        }
    }
}

void gas(std::vector<Ball> &balls, Table &t, int count, uint64_t seed) {
    const double side = std::sqrt(count * M_PI * kBallRadius * kBallRadius / kGasAreaFraction);
    t.length = t.width = side;
    const int per_row = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    const double cell = side / per_row;
    const double jitter = cell / 2 - kBallRadius * 1.01;
    Rng rng(seed);
    double mean_vx = 0, mean_vy = 0;
    for (int i = 0; i < count; ++i) {
        const int column = i % per_row, row = i / per_row; // integer division intended: grid cell
        const double cx = (column + 0.5) * cell, cy = (row + 0.5) * cell;
        Ball b = make_ball(cx + jitter * (2 * rng.uniform() - 1), cy + jitter * (2 * rng.uniform() - 1), i);
        // far from equilibrium on purpose: uniform components, not Gaussian
        b.vx = 2 * rng.uniform() - 1;
        b.vy = 2 * rng.uniform() - 1;
        mean_vx += b.vx;
        mean_vy += b.vy;
        balls.push_back(b);
    }
    mean_vx /= count;
    mean_vy /= count;
    for (Ball &b : balls) {
        b.vx -= mean_vx;
        b.vy -= mean_vy;
    }
}

}  // namespace

Layout set_up(Scene scene, int gas_balls, uint64_t seed) {
    Layout s;
    Table &t = s.table;
    t.length = kTableLength;
    t.width = kTableWidth;
    t.rail = 0.1;
    if (scene == Scene::Gas) {
        gas(s.balls, t, gas_balls, seed);
        t.rail = std::max(0.05, t.length / 40);
        add_rectangle_cushions(t);
    } else {
        s.balls.push_back(make_ball(head_spot_x(t), centre_line_y(t), 0));
        rack(s.balls, t, seed);
        if (scene == Scene::Break) add_pocketed_cushions(t);
        else add_rectangle_cushions(t);
    }
    return s;
}

Point free_head_spot(const Table &table, const std::vector<Ball> &balls) {
    Point p{head_spot_x(table), centre_line_y(table)};
    for (;;) {
        bool free = true;
        for (const Ball &b : balls)
            if (b.active && std::hypot(b.x - p.x, b.y - p.y) < kBallDiameter * 1.01) free = false;
        if (free || p.x < 2 * kBallDiameter) return p;
        p.x -= kBallRadius;
    }
}

}  // namespace demo
