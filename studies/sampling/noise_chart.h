#pragma once

#include <string>
#include <vector>

#include "studies/sampling/noise_study.h"

namespace raystep {

/// The sampling noise study as one SVG chart: a panel per scene, RMSE against the mean processor
/// time of a render, both axes logarithmic, a line per curve through its sample counts, each point
/// with a whisker of one spread up and down, and a legend with each curve's slope against N. The
/// colours follow SamplingKind, so that a colour means the same in every panel.
std::string noise_chart_svg(const std::vector<NoiseScene>& scenes);

}  // namespace raystep
