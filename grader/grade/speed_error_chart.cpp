#include "grader/grade/speed_error_chart.h"

#include <algorithm>
#include <chrono>
#include <fstream>

#include "grader/grade/build_locations.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/sandbox/sandbox.h"
#include "studies/speed_error/pareto_json.h"

namespace raystep::grade {

namespace {

double metric(const CheckResult& check, const char* name) {
    const auto found = check.metrics.find(name);
    return found == check.metrics.end() ? 0.0 : found->second;
}

}  // namespace

std::optional<nlohmann::json> speed_error_chart_data(const GradeReport& report,
                                                     const std::filesystem::path& reference_json) {
    const auto check = std::find_if(report.checks.begin(), report.checks.end(),
                                    [](const CheckResult& c) { return c.id == kSpeedErrorCheck; });
    if (check == report.checks.end() || check->outcome != Outcome::passed) return std::nullopt;

    std::ifstream in(reference_json);
    if (!in) return std::nullopt;
    nlohmann::json json;
    std::vector<ParetoFamily> families;
    try {
        json = nlohmann::json::parse(in);
        families = pareto_families_from_json(json);
    } catch (const nlohmann::json::exception&) {
        return std::nullopt;
    }
    const auto family = std::find_if(families.begin(), families.end(), [](const ParetoFamily& f) {
        return f.name == kSpeedErrorFamily;
    });
    if (family == families.end()) return std::nullopt;
    const auto cramer = std::find_if(
        family->points.begin(), family->points.end(),
        [](const ParetoPoint& p) { return p.function == "intersect_triangle_cramer"; });
    if (cramer == family->points.end()) return std::nullopt;

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
    return nlohmann::json{{"study", "pareto-family"},
                          {"footnote", footnote},
                          {"family", pareto_family_json(*family)}};
}

std::string draw_chart_svg(const nlohmann::json& data) {
    const std::string python = built_chart_python();
    if (python.empty()) return "";
    // Our script on our data: the sandbox only for its limits and its clean environment. The
    // data on stdin, the SVG on stdout.
    SandboxPolicy policy;
    policy.isolate = false;
    const std::filesystem::path script = built_chart_script();
    policy.read_only = {script};
    policy.limits.cpu_seconds = 30.0;
    policy.limits.wall = std::chrono::seconds(60);
    policy.limits.address_space_bytes = std::size_t{8} << 30;  // numpy's threads reserve much
    policy.limits.open_files = 256;
    SandboxRun run;
    try {
        run = run_sandboxed({python, script.string(), "-", "-o", "-"}, data.dump(), policy);
    } catch (const std::runtime_error&) {
        return "";  // the Python configured is gone
    }
    if (run.exit_code != 0 || run.timed_out || run.output_capped) return "";
    // Inline in the page: the <svg> element alone, without the file's XML declaration and DTD.
    const std::size_t start = run.output.find("<svg");
    const std::size_t end = run.output.rfind("</svg>");
    if (start == std::string::npos || end == std::string::npos || end < start) return "";
    return run.output.substr(start, end + 6 - start);
}

}  // namespace raystep::grade
