/* SPDX-License-Identifier: MIT */
// world_engine.h - the engine on the library's event-driven world
// (collide2d_world.h): the world keeps every ball's exact motion, orders the
// events and resolves the impacts; this engine only sets the scene up in it,
// advances it a frame at a time and turns the world's events into the
// demo's records (events.h) and the checker's view (engine.h: the pairs
// resolved and the waypoints where paths bend).
#ifndef C2D_DEMO_WORLD_ENGINE_H
#define C2D_DEMO_WORLD_ENGINE_H

#include <memory>
#include <vector>

#include "pool/engine.h"

namespace demo {

// Who finds the world's candidate pairs: Box2D's b2DynamicTree through the
// world's caller broadphase (c2d_world_desc.broadphase: Box2D finds
// candidates, the library resolves), or the world's built-in cells.  The
// events and states are the same bits either way (the world's contract);
// only the time differs.
// List: a caller broadphase that compares the query with every disk's box
// (in double), which the computer opponent uses for its many short runs on
// a table of 16 balls: cheaper than the tree there.
enum class WorldBroadphase { Tree, Cells, List };

std::unique_ptr<Engine> make_world_engine(const std::vector<Ball> &balls, const Table &table, const Model &model,
                                          WorldBroadphase broadphase = WorldBroadphase::Cells);

}  // namespace demo

#endif
