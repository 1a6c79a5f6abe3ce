/* SPDX-License-Identifier: MIT */
// engine_view.h - how the window reads the simulation: the table's shape as
// it is drawn and aimed at (the engine's cushions and pockets, with each
// nose's cushion face and a rail wide enough for the holes), and the
// contacts of a frame that make a sound.  demo/pool/NEEDS_FROM_ENGINE.md lists
// what the window asked of the engine and where it comes from.
#ifndef C2D_DEMO_ENGINE_VIEW_H
#define C2D_DEMO_ENGINE_VIEW_H

#include <vector>

#include "pool/sim.h"

namespace demo {

// One side of a pocket's mouth: the straight jaw facing (the line a ball's
// surface touches, a at the nose, n into the mouth), the rounded nose, and
// the normal of the cushion face the nose joins it to.
struct JawShape {
    Segment facing;
    double nose_x, nose_y, nose_r;
    double face_nx, face_ny;
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

// What made a sound in the last frame.
enum class ContactKind { BallBall, Cushion, Pocket, Strike };
struct Contact {
    ContactKind kind;
    double x, y;     // where, m
    double impulse;  // N s (a fall: the ball's momentum; a strike: m v)
    int ball;        // index into balls()
    int pocket;      // a fall: index into Table::pockets; otherwise -1
};
std::vector<Contact> frame_contacts(const Simulation &sim);

}  // namespace demo

#endif
