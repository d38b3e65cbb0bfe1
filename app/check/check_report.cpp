#include "app/check/check_report.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace raystep {

namespace {

// The value at rank ceil(fraction * n) of a sorted list (the nearest-rank percentile): always one
// of the measured values, never an interpolation between two.
double nearest_rank(const std::vector<double>& sorted, double fraction) {
    const auto rank =
        static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(sorted.size())));
    return sorted[std::max<std::size_t>(rank, 1) - 1];
}

std::size_t column_width(const std::vector<MethodScore>& scores, const char* heading,
                         std::string MethodScore::*field) {
    std::size_t width = std::string(heading).size();
    for (const MethodScore& score : scores)
        width = std::max(width, (score.*field).size());
    return width;
}

bool has_failures(const MethodScore& score) {
    return !score.not_implemented && score.passed < score.cases;
}

void print_counterexamples(std::FILE* out, const MethodScore& score, const std::string& rerun) {
    const std::size_t failed = score.cases - score.passed;
    std::fprintf(out, "\n%s on %s: %zu of %zu cases failed", score.method.c_str(),
                 score.family.c_str(), failed, score.cases);
    if (score.counterexamples.size() < failed) {
        std::fprintf(out, "; the first %zu", score.counterexamples.size());
    }
    std::fprintf(out, "\n");
    for (const Counterexample& example : score.counterexamples) {
        std::fprintf(out, "  case %llu: %s: %s\n",
                     static_cast<unsigned long long>(example.case_index),
                     verdict_name(example.verdict), example.detail.c_str());
        // The case as its file shows it, indented, so that it can be pasted into a file of its own.
        std::size_t start = 0;
        while (start < example.text.size()) {
            std::size_t end = example.text.find('\n', start);
            if (end == std::string::npos) end = example.text.size();
            std::fprintf(out, "    %.*s\n", static_cast<int>(end - start),
                         example.text.c_str() + start);
            start = end + 1;
        }
        std::fprintf(out, "  rerun: %s --family %s --method %s --case %llu\n", rerun.c_str(),
                     score.family.c_str(), score.method.c_str(),
                     static_cast<unsigned long long>(example.case_index));
    }
}

// Hits whose exact t is 0 within its tolerance stay out of the ulp columns (MethodScore): said
// under the table, with the absolute error, which does mean something there.
void print_hits_at_t_zero(std::FILE* out, const std::vector<MethodScore>& scores) {
    bool any = false;
    for (const MethodScore& score : scores) {
        if (score.not_implemented || score.hits_at_t_zero == 0) continue;
        if (!any) {
            std::fprintf(out,
                         "hits whose exact t is 0 within its tolerance (a ray that starts on "
                         "the surface, a sliver's wide tolerance), left out of the t ulps "
                         "columns, where a right t can be 1e15 ulps of 0 away:\n");
            any = true;
        }
        std::fprintf(out, "  %s on %s: %zu hits, largest |t - exact t| %.3g\n",
                     score.method.c_str(), score.family.c_str(), score.hits_at_t_zero,
                     score.largest_t_error_at_zero);
    }
}

}  // namespace

UlpSummary summarize_ulps(std::vector<double> ulps) {
    if (ulps.empty()) return {};
    std::sort(ulps.begin(), ulps.end());
    return {nearest_rank(ulps, 0.5), nearest_rank(ulps, 0.99), ulps.back()};
}

std::string ulp_text(double ulps) {
    char text[32];
    std::snprintf(text, sizeof text, ulps < 1e6 ? "%.0f" : "%.3g", ulps);
    return text;
}

void print_check_report(std::FILE* out, const std::vector<MethodScore>& scores,
                        const std::string& rerun) {
    const int method_width = static_cast<int>(column_width(scores, "method", &MethodScore::method));
    const int family_width = static_cast<int>(column_width(scores, "family", &MethodScore::family));

    std::fprintf(out, "%-*s  %-*s  %6s  %6s  %10s  %12s  %5s  %5s  %13s  %8s  %8s\n", method_width,
                 "method", family_width, "family", "cases", "pass", "false hits", "false misses",
                 "leaks", "other", "t ulps median", "p99", "max");
    // A stub fails on every family alike: one line says it.
    std::set<std::string> stubs_shown;
    for (const MethodScore& score : scores) {
        if (score.not_implemented) {
            if (stubs_shown.insert(score.method).second) {
                std::fprintf(out, "%-*s  not implemented: %s\n", method_width, score.method.c_str(),
                             score.not_implemented_message.c_str());
            }
            continue;
        }
        // A method that tests none of a family's primitives has nothing to show there.
        if (score.cases == 0) continue;

        const std::size_t false_hits = score.count(Verdict::false_hit);
        const std::size_t false_misses = score.count(Verdict::false_miss);
        const std::size_t leaks = score.count(Verdict::leak);
        const std::size_t other = score.cases - score.passed - false_hits - false_misses - leaks;
        // Rounded down, so that 100.0% means every case passed.
        const double pass_percent = std::floor(1000.0 * static_cast<double>(score.passed) /
                                               static_cast<double>(score.cases)) /
                                    10.0;
        // No t errors where the method reported no hit that the exact answer has.
        std::string median = "-";
        std::string p99 = "-";
        std::string max = "-";
        if (!score.t_ulps.empty()) {
            const UlpSummary summary = summarize_ulps(score.t_ulps);
            median = ulp_text(summary.median);
            p99 = ulp_text(summary.p99);
            max = ulp_text(summary.max);
        }
        std::fprintf(out, "%-*s  %-*s  %6zu  %5.1f%%  %10zu  %12zu  %5zu  %5zu  %13s  %8s  %8s\n",
                     method_width, score.method.c_str(), family_width, score.family.c_str(),
                     score.cases, pass_percent, false_hits, false_misses, leaks, other,
                     median.c_str(), p99.c_str(), max.c_str());
    }

    print_hits_at_t_zero(out, scores);
    for (const MethodScore& score : scores) {
        if (has_failures(score)) print_counterexamples(out, score, rerun);
    }
}

}  // namespace raystep
