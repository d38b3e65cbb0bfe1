#include "studies/structures/cross_check.h"

#include <numeric>

#include "base/math/to_text.h"
#include "studies/common/number_text.h"

namespace raystep {

namespace {

std::string answer_text(const BenchHit& hit) {
    if (hit.primitive == BenchHit::kMiss) return "a miss";
    return "primitive " + std::to_string(hit.primitive) + " at t = " + to_text(hit.t);
}

}  // namespace

AnswerComparison compare_answers(const std::vector<BenchHit>& a, std::size_t stride_a,
                                 const std::vector<BenchHit>& b, std::size_t stride_b) {
    AnswerComparison result;
    const std::size_t step = std::lcm(stride_a, stride_b);
    for (std::size_t ray = 0; ray / stride_a < a.size() && ray / stride_b < b.size(); ray += step) {
        const BenchHit& answer_a = a[ray / stride_a];
        const BenchHit& answer_b = b[ray / stride_b];
        ++result.compared;
        if (answer_a == answer_b) continue;
        if (result.differing == 0) {
            result.first_ray = ray;
            result.first_a = answer_a;
            result.first_b = answer_b;
        }
        ++result.differing;
    }
    return result;
}

std::vector<std::string> cross_check_lines(const std::vector<StructureMeasurement>& measurements,
                                           std::size_t ray_set) {
    std::vector<const StructureMeasurement*> ran;
    for (const StructureMeasurement& m : measurements) {
        if (!m.baseline && m.failure.empty() && ray_set < m.ray_sets.size()) ran.push_back(&m);
    }
    if (ran.size() < 2) return {};

    const StructureMeasurement& reference = *ran.front();
    const RayMeasurement& expected = reference.ray_sets[ray_set];
    std::vector<std::string> warnings;
    std::string agreeing;
    for (std::size_t k = 1; k < ran.size(); ++k) {
        const RayMeasurement& got = ran[k]->ray_sets[ray_set];
        const AnswerComparison c =
            compare_answers(expected.answers, expected.stride, got.answers, got.stride);
        if (c.differing == 0) {
            agreeing +=
                (agreeing.empty() ? "" : ", ") + ran[k]->name + " on " + grouped(c.compared);
            continue;
        }
        warnings.push_back("WARNING: " + ran[k]->name + " differs from " + reference.name + " on " +
                           grouped(c.differing) + " of " + grouped(c.compared) +
                           " rays; first ray " + std::to_string(c.first_ray) + ": " +
                           answer_text(c.first_b) + " against " + answer_text(c.first_a) +
                           ". Both must return closest_hit's answer: one of them has a bug.");
    }
    if (!agreeing.empty()) {
        warnings.insert(warnings.begin(), "cross-check: the same hits as " + reference.name + " (" +
                                              agreeing + " rays)");
    }
    return warnings;
}

}  // namespace raystep
