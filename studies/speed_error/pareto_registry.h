#pragma once

#include <string>
#include <vector>

#include "base/program/static_registry.h"

namespace raystep {

// The speed-against-error study (`bench --pareto`) measures the reference's extra tests and
// their float variants (solutions/3_intersect/single_precision.h) and writes JSON with
// nlohmann/json: neither belongs in the student-facing `raystep`. raystep-reference links the
// study as an object library whose static object registers it here, as the Embree baseline
// registers itself (studies/structures/baseline_registry.h).

/// `bench --pareto [--cases PATH]... [--out FOLDER] [--quick]`
struct ParetoOptions {
    std::vector<std::string> cases;  ///< case files or folders of them; none: stage 3's own
    std::string out_folder;          ///< where the charts and JSON go
    bool quick = false;              ///< shorter timing samples and one acne scene, for smoke tests
};

using ParetoStudy = int (*)(const ParetoOptions& options);

/// The study `bench --pareto` runs: none in a program that does not link it, one in
/// raystep-reference.
using ParetoStudyRegistry = StaticRegistry<ParetoStudy>;

}  // namespace raystep
