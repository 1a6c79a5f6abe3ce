/* SPDX-License-Identifier: MIT */
// box2d_engine.h - Box2D 2.4.1's own solver on the same scene, for
// comparison: it resolves contacts by impulses at the end of each step, so
// fast balls can pass through each other (the checker counts it).
#ifndef C2D_DEMO_BOX2D_ENGINE_H
#define C2D_DEMO_BOX2D_ENGINE_H

#include <memory>
#include <vector>

#include "pool/engine.h"

namespace demo {

std::unique_ptr<Engine> make_box2d_engine(const std::vector<Ball> &balls, const Table &table, const Model &model);

}  // namespace demo

#endif
