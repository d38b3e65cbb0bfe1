#pragma once

#include <vector>

#include "core/bench/bench_structure.h"

namespace raystep {

// The bench compares our structures with outside ones (Embree), which the student-facing
// `raystep` must not link: an outside library registers its baseline here from a static object,
// and only the programs that link that object (raystep-reference) see it.

/// Adds a baseline for every later bench run in this program; `candidate.baseline` is set.
void register_baseline(BenchCandidate candidate);

/// Every registered baseline, in the order they were registered.
const std::vector<BenchCandidate>& registered_baselines();

/// Registers a baseline when constructed: a static object of this type in the baseline's .cpp
/// adds it before main runs. The .cpp must be linked as an object (a CMake OBJECT library), not
/// from a static archive, whose unreferenced members the linker drops.
struct BaselineRegistration {
    explicit BaselineRegistration(BenchCandidate candidate);
};

}  // namespace raystep
