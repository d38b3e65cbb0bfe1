#include "app/check/check_report.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "base/testing/catch.h"

using namespace raystep;

namespace {

const std::string kRerun = "raystep check --stage 3 edges.cases";

std::string report(const std::vector<MethodScore>& scores) {
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    print_check_report(file, scores, kRerun);
    std::rewind(file);
    std::string text;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;)
        text.append(buffer, n);
    std::fclose(file);
    return text;
}

// The white-space separated fields of the report's first line that starts with `start`.
std::vector<std::string> row(const std::string& text, const std::string& start) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind(start, 0) != 0) continue;
        std::istringstream words(line);
        std::vector<std::string> fields;
        for (std::string word; words >> word;)
            fields.push_back(word);
        return fields;
    }
    return {};
}

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
        ++count;
    }
    return count;
}

MethodScore leaky_score() {
    MethodScore score;
    score.method = "intersect_triangle_cramer";
    score.family = "shared-edges";
    score.cases = 1000;
    score.passed = 997;
    score.counts[static_cast<int>(Verdict::pass)] = 997;
    score.counts[static_cast<int>(Verdict::leak)] = 2;
    score.counts[static_cast<int>(Verdict::wrong_t)] = 1;
    score.t_ulps = {2.0, 0.0, 1.0};
    score.counterexamples.push_back({17, Verdict::leak, "the ray slipped through",
                                     "case 17 watertight\nray 0 0 1 0 0 -1 0 inf\nend\n"});
    return score;
}

MethodScore stub_score(const std::string& family) {
    MethodScore score;
    score.method = "intersect_sphere";
    score.family = family;
    score.not_implemented = true;
    score.not_implemented_message = "stage 3: intersect_sphere is not implemented yet";
    return score;
}

}  // namespace

TEST_CASE("summarize_ulps: median, 99th percentile and maximum by nearest rank", "[app]") {
    const UlpSummary none = summarize_ulps({});
    CHECK(none.median == 0.0);
    CHECK(none.p99 == 0.0);
    CHECK(none.max == 0.0);

    std::vector<double> hundred(100);
    std::iota(hundred.begin(), hundred.end(), 1.0);
    std::shuffle(hundred.begin(), hundred.end(), std::mt19937(5));
    const UlpSummary summary = summarize_ulps(hundred);
    CHECK(summary.median == 50.0);
    CHECK(summary.p99 == 99.0);
    CHECK(summary.max == 100.0);

    // One large error in four: the median does not see it, the 99th percentile does.
    const UlpSummary outlier = summarize_ulps({0.0, 1000.0, 0.0, 0.0});
    CHECK(outlier.median == 0.0);
    CHECK(outlier.p99 == 1000.0);
    CHECK(outlier.max == 1000.0);
}

TEST_CASE("print_check_report: one row per method and family with its counts", "[app]") {
    MethodScore clean;
    clean.method = "intersect_plane";
    clean.family = "planes";
    clean.cases = 4;
    clean.passed = 4;
    const std::string text = report({leaky_score(), clean});
    CAPTURE(text);
    // 997 of 1000 is 99.7%; the t errors {0, 1, 2} have median 1, p99 and max 2.
    CHECK(row(text, "intersect_triangle_cramer") ==
          std::vector<std::string>{"intersect_triangle_cramer", "shared-edges", "1000", "99.7%",
                                   "0", "0", "2", "1", "1", "2", "2"});
    // No hit measured: no t error to summarize.
    CHECK(row(text, "intersect_plane") == std::vector<std::string>{"intersect_plane", "planes", "4",
                                                                   "100.0%", "0", "0", "0", "0",
                                                                   "-", "-", "-"});
}

TEST_CASE("print_check_report: hits at t = 0 are named under the table with their t error",
          "[app]") {
    MethodScore on_surface;
    on_surface.method = "intersect_plane";
    on_surface.family = "origins-on-surface";
    on_surface.cases = 26;
    on_surface.passed = 26;
    on_surface.hits_at_t_zero = 26;
    on_surface.largest_t_error_at_zero = 3.1e-17;
    const std::string text = report({on_surface});
    CAPTURE(text);
    CHECK(row(text, "intersect_plane") ==
          std::vector<std::string>{"intersect_plane", "origins-on-surface", "26", "100.0%", "0",
                                   "0", "0", "0", "-", "-", "-"});
    CHECK(text.find("intersect_plane on origins-on-surface: 26 hits, largest |t - exact t| "
                    "3.1e-17") != std::string::npos);
}

TEST_CASE("print_check_report: the pass rate rounds down, so 100% means all passed", "[app]") {
    MethodScore almost = leaky_score();
    almost.passed = 999;
    almost.counts[static_cast<int>(Verdict::leak)] = 1;
    almost.counts[static_cast<int>(Verdict::wrong_t)] = 0;
    almost.cases = 1000;
    const std::string text = report({almost});
    CAPTURE(text);
    CHECK(row(text, "intersect_triangle_cramer").at(3) == "99.9%");
}

TEST_CASE("print_check_report: a failing row's counterexamples with the command that reruns them",
          "[app]") {
    const std::string text = report({leaky_score()});
    CAPTURE(text);
    CHECK(text.find("\nintersect_triangle_cramer on shared-edges: 3 of 1000 cases failed; the "
                    "first 1\n"
                    "  case 17: leak: the ray slipped through\n"
                    "    case 17 watertight\n"
                    "    ray 0 0 1 0 0 -1 0 inf\n"
                    "    end\n"
                    "  rerun: raystep check --stage 3 edges.cases --family shared-edges --method "
                    "intersect_triangle_cramer --case 17\n") != std::string::npos);
}

TEST_CASE("print_check_report: a stub gets one line, however many families", "[app]") {
    const std::string text = report({stub_score("spheres"), stub_score("far-spheres")});
    CAPTURE(text);
    CHECK(occurrences(text, "not implemented:") == 1);
    CHECK(row(text, "intersect_sphere") ==
          std::vector<std::string>{"intersect_sphere", "not", "implemented:", "stage",
                                   "3:", "intersect_sphere", "is", "not", "implemented", "yet"});
    CHECK(occurrences(text, "rerun") == 0);
}

TEST_CASE("print_check_report: a method with no case in a family gets no row there", "[app]") {
    MethodScore nothing;
    nothing.method = "intersect_plane";
    nothing.family = "shared-edges";
    const std::string text = report({leaky_score(), nothing});
    CAPTURE(text);
    CHECK(occurrences(text, "intersect_plane") == 0);
}
