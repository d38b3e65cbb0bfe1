#include "studies/structures/speed_bar.h"

#include <algorithm>

#include "studies/common/number_text.h"

namespace raystep {

namespace {

const StructureMeasurement* measured(const std::vector<StructureMeasurement>& measurements,
                                     bool baseline, const std::string& name) {
    for (const StructureMeasurement& m : measurements) {
        if (m.failure.empty() && m.baseline == baseline && (baseline || m.name == name)) return &m;
    }
    return nullptr;
}

}  // namespace

std::vector<SpeedGoal> speed_goals() {
    return {{"bunny-primary", "primary rays on one thread", 0.8},
            {"bunny-incoherent", "incoherent rays on one thread", 0.5},
            {"", "build", 2.0}};
}

std::vector<std::string> speed_bar_lines(const std::string& scene,
                                         const std::vector<StructureMeasurement>& measurements,
                                         const std::vector<RaySet>& ray_sets) {
    if (scene != kSpeedBarScene) return {};
    const StructureMeasurement* ours = measured(measurements, false, "BVH SAH");
    const StructureMeasurement* theirs = measured(measurements, true, "");
    if (!ours || !theirs || ray_sets.empty()) return {};
    if (!theirs->isa.empty()) {
        return {"speed bar: not judged against " + theirs->name +
                ": the goals are set against the baseline at the best instructions the processor "
                "has"};
    }

    std::vector<std::string> lines;
    const std::string prefix = "speed bar, " + ours->name + " against " + theirs->name + ": ";
    for (const SpeedGoal& goal : speed_goals()) {
        double ratio = 0.0;
        bool met = false;
        if (goal.ray_set.empty()) {
            ratio = ours->build_seconds / theirs->build_seconds;
            met = ratio <= goal.ratio;
        } else {
            const auto set = std::find_if(ray_sets.begin(), ray_sets.end(),
                                          [&](const RaySet& s) { return s.name == goal.ray_set; });
            if (set == ray_sets.end()) continue;
            const auto k = static_cast<std::size_t>(set - ray_sets.begin());
            const RayMeasurement& a = ours->ray_sets[k];
            const RayMeasurement& b = theirs->ray_sets[k];
            ratio = mrays_per_second(a.rays, a.seconds_one_thread) /
                    mrays_per_second(b.rays, b.seconds_one_thread);
            met = ratio >= goal.ratio;
        }
        lines.push_back(prefix + goal.what + " " + three_digits(ratio) +
                        "x (goal: " + (goal.ray_set.empty() ? "at most " : "at least ") +
                        fixed(goal.ratio, 1) + "x): " + (met ? "met" : "NOT MET"));
    }
    return lines;
}

}  // namespace raystep
