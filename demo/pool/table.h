/* SPDX-License-Identifier: MIT */
// table.h - the table's geometry, shared by the engines (what a ball hits)
// and the window (what is drawn): the playing surface, the cushion faces,
// and six pockets with angled jaw facings, rounded jaw points (noses) and a
// hole.  SI units; x along the table, y across it, the playing surface is
// [0, length] x [0, width] between the cushion faces.
//
// Every line below is where the ball's *surface* touches (a ball touches a
// cushion when its centre is one radius in front of the line); every circle
// is a solid (a ball touches a nose when its centre is R + nose_r from the
// nose's centre), and a ball falls when its *centre* enters a hole.
//
// Pocket dimensions (WPA equipment specifications, 2001 and later: corner
// mouth 4.5-4.625 in, side mouth 5-5.125 in, facing angles 142 +- 1 and
// 104 +- 1 degrees, shelf 1-2.25 in corner, 0-0.375 in side):
//            mouth     facing   nose r   shelf    hole r
//   corner   117 mm    142 deg  16 mm    41 mm    63.5 mm
//   side     130 mm    104 deg   8 mm     6 mm    63.5 mm
// The mouth is measured between the theoretical jaw points (where a rail's
// cushion line meets the facing's line); the noses round that corner and
// start about 6 mm from it on each face.  A facing makes the stated angle
// with its rail's cushion line, inside the rubber, so a pocket narrows
// going in (a facing along the pocket's axis would make 135 / 90 degrees).
// The shelf is the slate between the mouth line and the hole; the hole is a
// circle on the pocket's axis whose nearest point is `shelf` behind the
// mouth line.  The facings run in to the depth of the hole's centre: a ball
// between them has fallen by then.
#ifndef C2D_DEMO_TABLE_H
#define C2D_DEMO_TABLE_H

#include <vector>

namespace demo {

struct Point { double x, y; };

// A straight face from a to b; n is its unit normal, pointing to the side
// the balls are on.
struct Segment { double ax, ay, bx, by, nx, ny; };

// One side of a pocket's mouth: the straight facing (a at the nose end, b at
// the throat end, n pointing into the mouth) and the rounded jaw point
// joining it to the rail's cushion face.
struct Jaw {
    Segment facing;
    double nose_x, nose_y, nose_r;
};

struct Pocket {
    double x, y;            // centre of the hole
    double capture_radius;  // the ball falls when its centre is closer than this to (x, y)
    Jaw jaws[2];
    Point mouth[2];         // the theoretical jaw points (the mouth is measured between them)
};

struct PocketSpec {
    double mouth;             // m, between the theoretical jaw points
    double facing_angle_deg;  // between the rail's cushion line and the facing, inside the rubber
    double nose_radius;       // m
    double shelf;             // m, mouth line to the hole's nearest point
    double hole_radius;       // m
};

struct TableSpec {
    double length = 2.54, width = 1.27;  // playing surface, cushion face to cushion face
    double rail = 0.1;                   // drawn rail, cushion included, beyond the surface
    PocketSpec corner{0.117, 142.0, 0.016, 0.041, 0.0635};
    PocketSpec side{0.130, 104.0, 0.008, 0.006, 0.0635};
};

struct Table {
    double length, width;          // playing surface [0,length] x [0,width]
    double rail;                   // drawn rail width
    std::vector<Segment> cushions; // the rails' cushion faces, n into the table
    std::vector<Pocket> pockets;   // corners (0,0), (L,0), (0,W), (L,W), then sides (L/2,0), (L/2,W)
};

// The pool table: six cushion faces between six pockets.
Table pool_table(const TableSpec &spec);
// A box with four full-length cushions and no pockets (elastic and gas scenes).
Table closed_box(double length, double width, double rail);

// The region of a pocket a ball's centre can reach beyond the cushion lines:
// the quadrilateral from the two jaw points down the facings (convex), plus
// the hole.
bool in_pocket_mouth(const Pocket &pocket, double x, double y);
// On the playing surface or in a pocket's mouth: where a ball's centre can be.
bool on_table(const Table &table, double x, double y);

}  // namespace demo

#endif
