/* SPDX-License-Identifier: MIT */
// checker.h - the independent frame checker.  It trusts neither engine: from
// the balls before and after a frame and the engine's log (the pairs it
// resolved, the points where paths bent), it counts
//   tunnelled  pairs that came into contact during the frame and are out the
//              other side without a contact the engine resolved;
//   overlap    the deepest ball-ball or ball-cushion overlap at the frame's
//              end, as a fraction of a diameter;
//   escaped    balls that left the playing surface and are not in a
//              pocket's mouth (each counted once);
//   energy     the largest relative change of the kinetic energy (rotation
//              included) from one frame to the next: either way in the
//              lossless scenes, a rise in the others (friction only takes).
// How much of it (CheckMode, --check):
//   full    every pair whose paths come near each other, every frame.
//   sample  the pair checks of a subset of the balls each frame: every
//           m-th ball (m = ceil(N / kSampledBalls), so up to kSampledBalls
//           balls it is full) from an offset drawn afresh each frame from
//           the run's seed, each checked against every ball near it; the
//           per-ball checks (cushion overlap, escape) and the energy stay
//           whole.  A tunnel or an overlap of a pair is seen in its frame
//           with probability at least 1 - (1 - 1/m)^2 ~ 2/m (either ball
//           sampled): at N = 100,000 (m = 98) 2 %, so a fault that strikes
//           230 times in a run, or an overlap that lasts 230 frames (4 s),
//           is seen with probability 99 %, one that strikes 1,000 times
//           with 1 - 2e-9; and every ball is sampled once every m frames
//           on average (37 times in a minute at N = 100,000).
//   off     nothing (tunnelled, max_overlap, escaped stay 0).
#ifndef C2D_DEMO_CHECKER_H
#define C2D_DEMO_CHECKER_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pool/engine.h"
#include "pool/scene.h"

namespace demo {

enum class CheckMode { Full, Sample, Off };

// The most balls a sampled frame checks the pairs of (CheckMode::Sample).
constexpr size_t kSampledBalls = 1024;

class Checker {
public:
    explicit Checker(CheckMode mode = CheckMode::Full, uint64_t seed = 1, bool lossless = false)
        : mode_(mode), seed_(seed), lossless_(lossless) {}
    CheckMode mode() const { return mode_; }
    // The frame took the balls from before to after in dt; sorts log.contacts.
    void check_frame(const std::vector<Ball> &before, const std::vector<Ball> &after, FrameLog &log,
                     const Table &table, double dt, Stats &stats);

private:
    void choose_sample(size_t n);
    void check_energy(const std::vector<Ball> &before, const std::vector<Ball> &after, Stats &stats) const;
    template <typename Visit> void for_each_sampled_pair(Visit visit);
    void build_grid();
    struct Box {
        double x0, y0, x1, y1;  // the path's box, radius included
        double x, y;            // the centre at the frame's end
    };
    void index_waypoints(const FrameLog &log, size_t n);
    void bound_paths(const std::vector<Ball> &before, const std::vector<Ball> &after);
    template <typename Visit> void for_each_close_pair(Visit visit);
    void count_escaped(const std::vector<Ball> &after, const Table &table, Stats &stats);

    std::vector<Box> box_;             // each live ball's path this frame, plus its radius
    std::vector<Box> cell_box_;        // the same in cell order (by_cell_)
    std::vector<char> live_;           // on the table before and after the frame
    std::vector<Waypoint> points_;     // this frame's waypoints, sorted by ball then time
    std::vector<size_t> first_;        // points_[first_[i] .. first_[i+1]) belong to ball i
    std::vector<size_t> cell_of_, cell_start_, by_cell_, fill_;
    std::vector<char> escaped_;
    std::vector<double> cuts_;         // a pair's piece boundaries (scratch)
    CheckMode mode_;
    uint64_t seed_;
    bool lossless_;
    uint64_t frame_ = 0;
    size_t stride_ = 1, offset_ = 0;   // the sample: balls offset_, offset_ + stride_, ...
    // the grid of for_each_close_pair: origin, cell width, cells a side
    double gx0_ = 0, gy0_ = 0, cell_ = 0;
    size_t nx_ = 0, ny_ = 0;
};

}  // namespace demo

#endif
