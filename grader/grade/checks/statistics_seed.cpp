#include "grader/grade/checks/statistics_seed.h"

#include <atomic>

namespace raystep::grade {

namespace {

// Set once by main before any check runs; atomic because checks run on several threads.
std::atomic<std::uint64_t> seed_in_force{kDefaultStatisticsSeed};

}  // namespace

std::uint64_t statistics_seed() {
    return seed_in_force.load();
}

void set_statistics_seed(std::uint64_t seed) {
    seed_in_force.store(seed);
}

}  // namespace raystep::grade
