#pragma once

#include <vector>

#include "app/protocol/probe_json.h"
#include "stages/4_accel/bvh.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep::probe {

// Stage 4's structures as data between a probe and the grader (grader/probe/README.md): a BVH's
// nodes and a grid's cells, which the grader checks and walks itself (docs/instructor.md, "What
// student code can touch"). Read as strictly as probe_json.h's values: a missing field, a
// negative or fractional index, a wrong type throws.

/// [{"min", "max", "children", "primitives"}, ...], root first.
Json bvh_nodes(const std::vector<BvhNodeData>& nodes);
std::vector<BvhNodeData> bvh_nodes_from(const Json& j);

/// {"min", "max", "resolution", "cells"}: the cells as lists of primitive numbers, x fastest.
Json uniform_grid_data(const UniformGridData& grid);
UniformGridData uniform_grid_data_from(const Json& j);

}  // namespace raystep::probe
