#pragma once

#include "app/check/ray_case.h"

namespace raystep {

/// The contract on hand-picked cases, which random families reach seldom: t ranges that cut a
/// hit off on either side, triangles in the coordinate planes, triangles whose normal lies on or
/// next to each positive and negative axis, rays nearly parallel to a plane that cross it, the
/// nearest of several primitives, copies of one primitive (a tie), slivers whose inward normal
/// rounds to zero. Cases without expectations: grader/oracle decides them.
CaseFamily contract_family();

/// The contract's exact sentences, on cases every correct test computes without rounding (small
/// dyadic coordinates, axis-parallel rays and edges, powers of two at the domain's ends): t_min
/// and t_max included, edges and vertices on the triangle, two-sided surfaces, a ray in a plane
/// a miss and one a power of two off parallel a hit, degenerate input a miss, ties across kinds,
/// the domain. Decide them, then tighten them with tighten_exact_family.
CaseFamily exact_family();

/// No rounding can move an exact case: clears every near_boundary and makes every hit's
/// t_tolerance zero, which also lets closest_hit's scoring decide ties across kinds.
void tighten_exact_family(CaseFamily& family);

}  // namespace raystep
