#pragma once

#include <cstdint>

namespace raystep::grade {

// The seed of the grader's statistical checks (stage 8's): the RandomStream seed their queries
// hand the probe. A right submission passes them at every seed at their stated false-fail rate,
// so the seed changes nothing but which random numbers are drawn; a fixed default makes a grade
// reproducible, and `raystep-grade submission --seed S` draws others, which is how the false-fail
// rates are measured (docs/measurements/stage8-checks.md). Stage 3's contract checks draw their
// cases from it too (docs/measurements/stage3-check-power.md).

inline constexpr std::uint64_t kDefaultStatisticsSeed = 8;

/// The seed in force: kDefaultStatisticsSeed unless set.
std::uint64_t statistics_seed();

/// Sets it for every statistical check made after the call (raystep-grade's --seed).
void set_statistics_seed(std::uint64_t seed);

}  // namespace raystep::grade
