#pragma once

#include <cstddef>
#include <cstdint>

#include "app/check/ray_case.h"

namespace raystep {

// Stage 3's contract edges, one family for each sentence of intersect.h that the random families
// reach seldom and a right test never gets wrong: a few hand-picked cases, then `count` drawn from
// `seed` (case k of the draw from its own generator, PortableRandom(seed + salt, k)). Without
// expectations: grader/oracle decides them. The grader's stage3.contract checks ask each function
// of intersect.h every case of a family that has a primitive it tests.

/// t = t_min and t = t_max exactly, both ends included, and hits a step beyond either end, which
/// are misses: planes and triangles met by oblique rays, spheres met along an axis at the near
/// root or the far one, a hit at an end among other primitives. Every number dyadic
/// (dyadic_hits.h), so every right test computes t exactly: decide them, then hold them exact with
/// tighten_exact_family.
CaseFamily range_end_family(std::uint64_t seed, std::size_t count);

/// Ties in closest_hit: copies of one primitive, different primitives of one kind met at one t,
/// and a sphere, triangles and planes met at one t, in shuffled lists with a farther primitive of
/// the same kind listed before them. The primitive first in closest_hit's order (spheres, then
/// triangles, then planes, each in list order) must win. Exact: decide, then tighten.
CaseFamily tie_family(std::uint64_t seed, std::size_t count);

/// Rays lying in a plane, or in a triangle's plane through it or beside it, from outside and from
/// within: a miss by the contract, alone and beside a primitive the ray does cross, which
/// closest_hit must return. Exact (D . N is exactly zero in every right test): decide, then
/// tighten.
CaseFamily in_plane_family(std::uint64_t seed, std::size_t count);

/// Degenerate input, a miss and never a NaN or a throw: collinear triangles drawn so that Cramer's
/// rule or Moller-Trumbore, without a test for a zero normal, finds a rounded hit
/// (collinear_triangles.h), some with a plane behind them for closest_hit; a repeated vertex; a
/// zero direction against every kind; a zero radius; a zero plane normal. The rays are not exact
/// (the planes behind are met at a rounded t): decide them only, the oracle's answer for a
/// degenerate primitive is a miss that no rounding excuses.
CaseFamily degenerate_family(std::uint64_t seed, std::size_t count);

}  // namespace raystep
