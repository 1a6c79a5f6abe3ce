/* SPDX-License-Identifier: MIT */
// exact_engine.h - the exact engine: every ball moves in closed form between
// events (motion.h: quadratic in t), events are found and processed in time
// order, impacts are resolved with collide2d; a broadphase (broadphase.h)
// only proposes candidate pairs: Box2D's dynamic tree, or with cell_grid a
// uniform grid (the gas: many balls spread evenly over a large box).
#ifndef C2D_DEMO_EXACT_ENGINE_H
#define C2D_DEMO_EXACT_ENGINE_H

#include <memory>
#include <vector>

#include "pool/engine.h"

namespace demo {

std::unique_ptr<Engine> make_exact_engine(const std::vector<Ball> &balls, const Table &table, const Model &model,
                                          bool cell_grid = false);

}  // namespace demo

#endif
