// exact_engine.h - the exact engine: impacts found in time order and
// resolved with collide2d; Box2D's dynamic tree only proposes candidates.
#ifndef C2D_DEMO_EXACT_ENGINE_H
#define C2D_DEMO_EXACT_ENGINE_H

#include <memory>
#include <vector>

#include "engine.h"

namespace demo {

std::unique_ptr<Engine> make_exact_engine(const std::vector<Ball> &balls, const Table &table, Restitution restitution);

}  // namespace demo

#endif
