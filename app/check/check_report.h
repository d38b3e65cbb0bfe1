#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "app/check/case_scoring.h"

namespace raystep {

/// The median, 99th percentile and maximum of a list of ulp errors (0 for an empty list).
struct UlpSummary {
    double median = 0.0;
    double p99 = 0.0;
    double max = 0.0;
};
UlpSummary summarize_ulps(std::vector<double> ulps);

/// An ulp count for a table: whole ulps up to a million as they are; beyond, 3 significant digits
/// tell enough (4.3e+08).
std::string ulp_text(double ulps);

/// Prints the scores as a table, one row per method and family: cases, pass rate, false hits,
/// false misses, leaks, other failures, t error in ulps (median, p99, max); then each failing
/// row's first counterexamples with their inputs and `rerun` (a command that runs just that case).
void print_check_report(std::FILE* out, const std::vector<MethodScore>& scores,
                        const std::string& rerun);

}  // namespace raystep
