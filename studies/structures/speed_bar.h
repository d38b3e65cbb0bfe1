#pragma once

#include <string>
#include <vector>

#include "studies/structures/measurement.h"

namespace raystep {

/// One goal of stage 4's speed bar for the reference BVH (BVH SAH), against the baseline on
/// bunny00.off, from ratios measured in the same run.
struct SpeedGoal {
    std::string ray_set;  ///< the workload whose one-thread throughput counts; empty for the build
    std::string what;     ///< "primary rays on one thread"
    double ratio;         ///< throughput: ours / theirs at least this; build: ours / theirs at most
};

/// Primary rays at least 0.8 times the baseline's throughput, incoherent rays 0.5 times, the build
/// at most 2 times its time.
std::vector<SpeedGoal> speed_goals();

/// The scene the speed bar is measured on.
inline constexpr const char* kSpeedBarScene = "bunny";

/// For the speed bar's scene: a line per goal whose workload was measured, with the ratio and
/// whether the goal is met. None for another scene, or when BVH SAH or the baseline was not
/// measured; one line saying the bar is not judged when the baseline was held to an instruction
/// set (BenchCandidate::isa).
std::vector<std::string> speed_bar_lines(const std::string& scene,
                                         const std::vector<StructureMeasurement>& measurements,
                                         const std::vector<RaySet>& ray_sets);

}  // namespace raystep
