#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "studies/structures/measurement.h"

namespace raystep {

/// One mesh size of the growth table.
struct GrowthRow {
    std::size_t triangles = 0;
    std::vector<StructureMeasurement> measurements;  ///< one per candidate, in their order
};

/// The growth table's rings around the torus axis, r = 16, 32, ..., 512: bumpy tori of r rings
/// by 2r segments, 4 r^2 triangles, 1,024 to 1,048,576.
std::vector<int> growth_rings();

/// Brute force is measured on the growth table's meshes up to this many triangles: beyond, even
/// a subsample of rays says nothing the smaller ones do not.
inline constexpr std::size_t kGrowthBruteForceLimit = 4096;

/// Measures every candidate on each bumpy torus (studies/structures/bumpy_torus.h) with `rays`
/// incoherent rays, builds and one thread only. Subsampled candidates stop at
/// kGrowthBruteForceLimit triangles.
std::vector<GrowthRow> measure_growth(const std::vector<BenchCandidate>& candidates,
                                      std::size_t rays, const MeasureOptions& options);

/// The table: a row per mesh, and for each structure its build ms and Mrays/s on one thread;
/// "-" where a structure was skipped. A list after it says where a structure ran on a subsample
/// of the rays, and which structures failed, and why.
std::string growth_table(const std::vector<GrowthRow>& rows);

}  // namespace raystep
