#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/epsilon/offset_cost.h"
#include "studies/speed_error/pareto_study.h"

namespace raystep {

/// One acne scene's offset rules: what each costs and gets wrong (docs/stage6.md).
struct OffsetRuleResult {
    std::string scene;
    std::string rule;      ///< "along-ray", "along-normal", "error-bound"
    double epsilon = 0.0;  ///< 0 for error-bound
    double nanoseconds_per_ray = 0.0;
    std::size_t acne = 0;
    std::size_t leaks = 0;
    std::size_t decided = 0;  ///< the pixel-light pairs whose exact answer is known
};

/// Everything `bench --pareto` measured, as the JSON file it writes, which scripts/draw-charts.py
/// draws: {"study": "pareto", "machine", "date",
/// "families": [{"name", "description", "cases", "points": [{"label", "precision",
/// "function", "cases", "false_hits", "false_misses", "wrong_share", "t_ulps": {"median",
/// "p99", "max"}, "mrays_per_second"}]}], "offset_rules": [{"scene", "rule", "epsilon",
/// "nanoseconds_per_ray", "acne", "leaks", "decided"}]}.
nlohmann::json pareto_json(const std::string& machine, const std::string& date,
                           const std::vector<ParetoFamily>& families,
                           const std::vector<OffsetRuleResult>& offset_rules);

/// One family as that JSON holds it: {"name", "description", "cases", "points"}.
nlohmann::json pareto_family_json(const ParetoFamily& family);

/// The families back from that JSON, for a chart that adds a point to them (the grader's
/// report). Throws nlohmann::json::exception for JSON of another shape.
std::vector<ParetoFamily> pareto_families_from_json(const nlohmann::json& json);

}  // namespace raystep
