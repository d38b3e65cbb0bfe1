#pragma once

#include "base/program/static_registry.h"
#include "studies/structures/bench_structure.h"

namespace raystep {

/// The outside structures the bench compares ours with (Embree), which the student-facing
/// `raystep` must not link: a baseline registers itself from a static object in its own .cpp file,
/// and only the programs that link that object (raystep-reference) see it. Each entry's
/// `baseline` is set.
using BaselineRegistry = StaticRegistry<BenchCandidate>;

}  // namespace raystep
