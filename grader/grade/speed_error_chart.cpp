#include "grader/grade/speed_error_chart.h"

#include <algorithm>
#include <fstream>

#include "grader/grade/checks/stage_checks.h"
#include "studies/speed_error/pareto_chart.h"
#include "studies/speed_error/pareto_json.h"

namespace raystep::grade {

namespace {

double metric(const CheckResult& check, const char* name) {
    const auto found = check.metrics.find(name);
    return found == check.metrics.end() ? 0.0 : found->second;
}

}  // namespace

std::string speed_error_chart_svg(const GradeReport& report,
                                  const std::filesystem::path& pareto_json) {
    const auto check = std::find_if(report.checks.begin(), report.checks.end(),
                                    [](const CheckResult& c) { return c.id == kSpeedErrorCheck; });
    if (check == report.checks.end() || check->outcome != Outcome::passed) return "";

    std::ifstream in(pareto_json);
    if (!in) return "";
    nlohmann::json json;
    std::vector<ParetoFamily> families;
    try {
        json = nlohmann::json::parse(in);
        families = pareto_families_from_json(json);
    } catch (const nlohmann::json::exception&) {
        return "";
    }
    const auto family = std::find_if(families.begin(), families.end(), [](const ParetoFamily& f) {
        return f.name == kSpeedErrorFamily;
    });
    if (family == families.end()) return "";
    const auto cramer = std::find_if(
        family->points.begin(), family->points.end(),
        [](const ParetoPoint& p) { return p.function == "intersect_triangle_cramer"; });
    if (cramer == family->points.end()) return "";

    ParetoPoint yours;
    yours.label = "your intersect_triangle";
    yours.precision = "submission";
    yours.function = "intersect_triangle";
    yours.cases = static_cast<std::size_t>(metric(*check, kSpeedErrorCases));
    yours.false_hits = static_cast<std::size_t>(metric(*check, kSpeedErrorFalseHits));
    yours.false_misses = static_cast<std::size_t>(metric(*check, kSpeedErrorFalseMisses));
    yours.t_ulps_median = metric(*check, kSpeedErrorUlpsMedian);
    yours.t_ulps_p99 = metric(*check, kSpeedErrorUlpsP99);
    yours.mrays_per_second = metric(*check, kSpeedErrorAgainstCramer) * cramer->mrays_per_second;
    family->points.push_back(yours);

    const std::string footnote = "Circles: raystep-reference bench --pareto, " +
                                 json.value("date", std::string("undated")) +
                                 ". Diamond: yours on " + std::to_string(yours.cases) +
                                 " cases, timed against the reference's Cramer.";
    return pareto_chart_svg(*family, footnote);
}

}  // namespace raystep::grade
