/* SPDX-License-Identifier: MIT */
// checker.h - the independent frame checker.  It trusts neither engine: from
// the balls before and after a frame and the engine's log (the pairs it
// resolved, the points where paths bent), it counts
//   tunnelled  pairs that came into contact during the frame and are out the
//              other side without a contact the engine resolved;
//   overlap    the deepest ball-ball or ball-cushion overlap at the frame's
//              end, as a fraction of a diameter;
//   escaped    balls that left the playing surface and are not in a
//              pocket's mouth (each counted once).
#ifndef C2D_DEMO_CHECKER_H
#define C2D_DEMO_CHECKER_H

#include <cstddef>
#include <vector>

#include "pool/engine.h"
#include "pool/scene.h"

namespace demo {

class Checker {
public:
    // The frame took the balls from before to after in dt; sorts log.contacts.
    void check_frame(const std::vector<Ball> &before, const std::vector<Ball> &after, FrameLog &log,
                     const Table &table, double dt, Stats &stats);

private:
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
};

}  // namespace demo

#endif
