#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace raystep::grade {

// How often a seeded check fails a submission known to be right: its checks run on one built
// probe at many statistical seeds (statistics_seed.h), so that a check's false-fail rate is
// measured rather than only stated (`raystep-grade seeds`, docs/measurements/stage8-checks.md).

/// The seeds at which each check did not pass, by check id.
struct SeedSweep {
    std::vector<std::string> checks;  ///< the checks run, in all_checks() order
    std::map<std::string, std::vector<std::uint64_t>> failed;
    std::vector<std::uint64_t> any_failed;  ///< the seeds at which at least one check failed
    std::uint64_t first = 0;
    int count = 0;
};

/// Runs every check whose id starts with `prefix` on `probe` (a probe program built by
/// raystep-grade, kept with --keep-work) at seeds first to first + count - 1, render checks on the
/// scenes under `source`/scenes, their images written into a temporary folder removed after.
/// Throws std::invalid_argument when no check has that prefix.
SeedSweep sweep_seeds(const std::filesystem::path& probe, const std::filesystem::path& source,
                      const std::string& prefix, std::uint64_t first, int count);

/// The sweep as a Markdown table, a row per check and one for any of them: the seeds failed and
/// the first few of them.
std::string seed_sweep_text(const SeedSweep& sweep);

}  // namespace raystep::grade
