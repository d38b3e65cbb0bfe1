#pragma once

#include "app/check/ray_case.h"

namespace raystep {

/// The contract on hand-picked cases, which random families reach seldom: t ranges that cut a
/// hit off among several primitives, triangles in the coordinate planes, triangles whose normal
/// lies on or next to each positive and negative axis, rays nearly parallel to a plane that cross
/// it, the nearest of several primitives, slivers whose inward normal rounds to zero. Cases without
/// expectations: grader/oracle decides them. The range's ends, ties, rays in a plane and
/// degenerate input are families of their own (stage3_contract_edges.h).
CaseFamily contract_family();

/// The contract's exact sentences, on cases every correct test computes without rounding (small
/// dyadic coordinates, axis-parallel rays and edges, powers of two at the domain's ends): edges
/// and vertices on the triangle, a tangent ray a hit, two-sided surfaces, a ray a power of two
/// off parallel a hit, the domain. Decide them, then tighten them with tighten_exact_family.
CaseFamily exact_family();

/// No rounding can move an exact case: clears every near_boundary and every alternative t (a
/// sphere's far root where the near one is at t_min), and makes every hit's t_tolerance zero,
/// which also lets closest_hit's scoring decide ties across kinds.
void tighten_exact_family(CaseFamily& family);

}  // namespace raystep
