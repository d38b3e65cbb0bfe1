#include "core/bench/baseline_registry.h"

#include <utility>

namespace raystep {

namespace {

// A function-local static, so that registrations from other files' static objects find it built
// whatever order the linker put the files in.
std::vector<BenchCandidate>& registry() {
    static std::vector<BenchCandidate> baselines;
    return baselines;
}

}  // namespace

void register_baseline(BenchCandidate candidate) {
    candidate.baseline = true;
    registry().push_back(std::move(candidate));
}

const std::vector<BenchCandidate>& registered_baselines() {
    return registry();
}

BaselineRegistration::BaselineRegistration(BenchCandidate candidate) {
    register_baseline(std::move(candidate));
}

}  // namespace raystep
