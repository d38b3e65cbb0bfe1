#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "stages/4_accel/bvh.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep::grade {

// A stage-4 structure as the probe hands it back (Bvh::nodes, UniformGrid::cells), checked and
// walked here, in the grader: the work a structure saves is counted on data the grader has
// validated, never by anything that runs in the probe (docs/instructor.md, "What student code can
// touch").

/// Why `nodes` is not a BVH over the spheres and triangles of `primitives`, in words, or nullopt
/// when it is one: a tree from node 0 (every other node the child of exactly one node, none out of
/// range), every primitive in some leaf, and every box holding its children's boxes and its leaf's
/// primitives' boxes, to within a millionth of the scene's size (room for boxes kept in float).
std::optional<std::string> bvh_problem(const std::vector<BvhNodeData>& nodes,
                                       const PrimitiveList& primitives);

/// Why `grid` is not a uniform grid over them, or nullopt when it is: a finite box that holds every
/// primitive, at least one cell along each axis and a list for each cell, and every primitive
/// listed in every cell its box overlaps by more than that same millionth (a box lying exactly on
/// a plane between cells may be listed on either side).
std::optional<std::string> grid_problem(const UniformGridData& grid,
                                        const PrimitiveList& primitives);

/// What the grader's own walk of a structure costs each ray.
struct WalkCost {
    std::vector<std::uint64_t> nodes;  ///< BVH nodes entered, or grid cells visited
    std::vector<std::uint64_t> tests;  ///< primitives tested, each at most once per ray
};

/// The lecture's walk of a valid BVH: nodes entered nearest first, a node skipped once it starts
/// beyond the best hit, each primitive tested once (a mailbox), with the reference's stage 3.
WalkCost walk_bvh(const std::vector<BvhNodeData>& nodes, const PrimitiveList& primitives,
                  const std::vector<Ray>& rays);

/// The lecture's walk of a valid grid: the 3D-DDA of Amanatides and Woo from the cell where the
/// ray enters, stopping once the next cell begins beyond the best hit, each primitive tested once.
WalkCost walk_grid(const UniformGridData& grid, const PrimitiveList& primitives,
                   const std::vector<Ray>& rays);

}  // namespace raystep::grade
