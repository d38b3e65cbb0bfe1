#pragma once

#include <string>

#include "studies/speed_error/pareto_study.h"

namespace raystep {

/// The family's chart as an SVG image: two panels with throughput across (Mrays/s, one
/// thread), wrong answers (false hits and misses, % of cases, log scale) up on the left and the
/// median t error (double ulps, log scale, a whisker up to the 99th percentile) up on the right.
/// A colour per method; double filled, float open. Points whose precision is neither (a
/// submission's method, in the grader's report) are drawn as a black diamond, labelled.
/// `footnote` goes under the legend: where and when it was measured.
std::string pareto_chart_svg(const ParetoFamily& family, const std::string& footnote);

}  // namespace raystep
