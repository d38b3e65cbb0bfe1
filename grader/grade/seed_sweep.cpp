#include "grader/grade/seed_sweep.h"

#include <stdexcept>
#include <system_error>

#include <unistd.h>

#include "grader/grade/check_definition.h"
#include "grader/grade/checks/statistics_seed.h"

namespace raystep::grade {

SeedSweep sweep_seeds(const std::filesystem::path& probe, const std::filesystem::path& source,
                      const std::string& prefix, std::uint64_t first, int count) {
    std::vector<CheckDefinition> checks;
    for (CheckDefinition& check : all_checks()) {
        if (check.id.rfind(prefix, 0) == 0) checks.push_back(std::move(check));
    }
    if (checks.empty()) throw std::invalid_argument("no check id starts with " + prefix);
    SeedSweep sweep;
    sweep.first = first;
    sweep.count = count;
    for (const CheckDefinition& check : checks) {
        sweep.checks.push_back(check.id);
        sweep.failed[check.id];
    }
    const BuiltProbe built{probe, ""};
    GradingContext context;
    context.reproduce = "raystep-grade seeds";
    context.source = source;
    context.grader_source = source;
    context.report_folder =
        std::filesystem::temp_directory_path() / ("raystep-seeds-" + std::to_string(::getpid()));
    for (int k = 0; k < count; ++k) {
        const std::uint64_t seed = first + static_cast<std::uint64_t>(k);
        set_statistics_seed(seed);
        bool any = false;
        for (const CheckDefinition& check : checks) {
            if (check.measure(context, built).outcome != Outcome::passed) {
                sweep.failed[check.id].push_back(seed);
                any = true;
            }
        }
        if (any) sweep.any_failed.push_back(seed);
    }
    std::error_code ignored;
    std::filesystem::remove_all(context.report_folder, ignored);
    return sweep;
}

std::string seed_sweep_text(const SeedSweep& sweep) {
    std::string text = "| check | seeds failed, of " + std::to_string(sweep.count) + " (" +
                       std::to_string(sweep.first) + " to " +
                       std::to_string(sweep.first + static_cast<std::uint64_t>(sweep.count) - 1) +
                       ") | the first of them |\n|---|---|---|\n";
    const auto row = [&text](const std::string& name, const std::vector<std::uint64_t>& failed) {
        std::string seeds;
        for (std::size_t k = 0; k < failed.size() && k < 5; ++k)
            seeds += (k ? ", " : "") + std::to_string(failed[k]);
        text += "| " + name + " | " + std::to_string(failed.size()) + " | " + seeds + " |\n";
    };
    for (const std::string& id : sweep.checks)
        row(id, sweep.failed.at(id));
    row("any of them", sweep.any_failed);
    return text;
}

}  // namespace raystep::grade
