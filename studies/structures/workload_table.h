#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "studies/structures/measurement.h"

namespace raystep {

/// The table of ray set `ray_set` over one scene's measurements, a row per structure: build ms,
/// Mrays/s on one thread and on `threads` threads, nodes and primitive tests per ray ("-" where
/// the structure does not count them). When a baseline was among the candidates, a column after
/// build ms and after each Mrays/s gives ours divided by the baseline's ("-" where either is
/// missing). A structure that was not measured has its reason in place of the numbers.
std::string workload_table(const std::vector<StructureMeasurement>& measurements,
                           std::size_t ray_set, int threads);

/// The lines under the table: which rays a subsampled structure ran, a baseline's build on one
/// thread, and the cross-check.
std::vector<std::string> workload_notes(const std::vector<StructureMeasurement>& measurements,
                                        std::size_t ray_set, std::size_t ray_count);

}  // namespace raystep
