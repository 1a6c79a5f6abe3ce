/* SPDX-License-Identifier: MIT */
// broadphase.h - candidate pairs from Box2D's b2DynamicTree: boxes (in
// Box2D units) with a tag, and the query "every box that overlaps this
// one".  The pool scenes' world engine plugs the dynamic tree into the
// world's caller-supplied broadphase (world_engine.cpp: Box2D finds the
// candidates, the library resolves).  Two answers to the query:
//   dynamic tree  Box2D's b2DynamicTree: any sizes, any spread; the pool
//                 scenes' broadphase;
//   cell grid     a uniform grid of square cells over a fixed region, each
//                 box listed in the cell of its lower-left corner (larger
//                 boxes than a cell in a list of their own); a query visits
//                 the cells around its box.  For many boxes of about one size
//                 spread evenly (the gas: disks' swept boxes, at most three
//                 diameters across), with cells a little larger a query reads
//                 a dozen or two entries whatever the count, and a move
//                 rewrites one entry, where the tree descends some 2 log2 N
//                 levels of nodes scattered in memory and re-inserts a moved
//                 box from the root.
// Both report exactly the boxes that overlap the query (touching counts, as
// b2TestOverlap), each once; only the order of the tags differs.
#ifndef C2D_DEMO_BROADPHASE_H
#define C2D_DEMO_BROADPHASE_H

#include <box2d/box2d.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace demo {

class Broadphase {
public:
    virtual ~Broadphase() = default;
    // A new box with its tag; returns its handle.
    virtual int32 add(const b2AABB &box, uintptr_t tag) = 0;
    virtual void move(int32 proxy, const b2AABB &box) = 0;
    virtual void remove(int32 proxy) = 0;
    // Appends to tags the tag of every box that overlaps `box`, once each.
    virtual void query(const b2AABB &box, std::vector<uintptr_t> &tags) = 0;
};

std::unique_ptr<Broadphase> make_dynamic_tree();

// A grid of square cells `cell` units wide over `region`; a box beyond the
// region is listed in the border cells it faces, so nothing is ever missed,
// only slower to find.
std::unique_ptr<Broadphase> make_cell_grid(const b2AABB &region, float cell);

}  // namespace demo

#endif
