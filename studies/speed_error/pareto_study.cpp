#include "studies/speed_error/pareto_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <variant>

#include "app/check/case_scoring.h"
#include "app/check/check_report.h"
#include "studies/common/bench_timing.h"
#include "studies/common/markdown_table.h"
#include "studies/common/number_text.h"

namespace raystep {

namespace {

// The timing runs on at most this many (ray, primitive) pairs, the family's first: about 300 KB,
// which stays in the processor's second-level cache, so that the time is the test's arithmetic
// and not the memory streaming a large case file past it, the same for every method.
constexpr std::size_t kTimedPairs = 2048;

// The family's first (ray, primitive) pairs that the method tests, in case order: the rays the
// timing runs, the same for every method of a shape.
struct TimedPairs {
    std::vector<Ray> rays;
    std::vector<CaseShape> shapes;
};

TimedPairs pairs_for(const Stage3Method& method, const CaseFamily& family) {
    TimedPairs pairs;
    for (const RayCase& ray_case : family.cases) {
        for (const CasePrimitive& primitive : ray_case.primitives) {
            if (!applies_to(method, primitive.shape)) continue;
            if (pairs.rays.size() == kTimedPairs) return pairs;
            pairs.rays.push_back(ray_case.ray);
            pairs.shapes.push_back(primitive.shape);
        }
    }
    return pairs;
}

// Runs the test on every pair once; the hits are counted so that the calls cannot be dropped.
std::size_t run_pairs(const Stage3Method& method, const TimedPairs& pairs) {
    std::size_t hits = 0;
    for (std::size_t k = 0; k < pairs.rays.size(); ++k) {
        const CaseShape& shape = pairs.shapes[k];
        if (const auto* sphere = std::get_if<Sphere>(&shape)) {
            hits += method.sphere(pairs.rays[k], *sphere).has_value();
        } else if (const auto* triangle = std::get_if<Triangle>(&shape)) {
            hits += method.triangle(pairs.rays[k], *triangle).has_value();
        } else {
            hits += method.plane(pairs.rays[k], std::get<Plane>(shape)).has_value();
        }
    }
    return hits;
}

// Millions of tests a second: passes over the pairs are repeated until a sample lasts
// timing.sample_seconds, and the fastest sample counts.
double tests_per_microsecond(const Stage3Method& method, const TimedPairs& pairs,
                             const ParetoTiming& timing) {
    if (pairs.rays.empty()) return 0.0;
    volatile std::size_t sink = 0;
    std::size_t passes = 1;
    while (seconds_of([&] {
               for (std::size_t p = 0; p < passes; ++p)
                   sink = sink + run_pairs(method, pairs);
           }) < timing.sample_seconds) {
        passes *= 2;
    }
    const double best = best_of(timing.samples, [&] {
        for (std::size_t p = 0; p < passes; ++p)
            sink = sink + run_pairs(method, pairs);
    });
    return static_cast<double>(passes * pairs.rays.size()) / best * 1e-6;
}

ParetoPoint score_point(const ParetoMethod& entry, const CaseFamily& family) {
    std::vector<CaseAnswer> answers;
    answers.reserve(family.cases.size());
    for (const RayCase& ray_case : family.cases)
        answers.push_back(run_method(entry.method, ray_case));
    const MethodScore score = score_family(entry.method, family, answers, 0);
    if (score.not_implemented) {
        throw std::runtime_error(entry.method.name + ": " + score.not_implemented_message);
    }

    ParetoPoint point;
    point.label = entry.label;
    point.precision = entry.precision;
    point.function = entry.method.name;
    point.cases = score.cases;
    // Against the exact answer for every method, near a boundary or not: the grading's "either
    // passes" near a boundary would hide a form's hits on exact misses. A leak (an exact hit on
    // the group that no primitive of it reported) is a false miss.
    point.false_hits = score.exact_false_hits;
    point.false_misses = score.exact_false_misses;
    // A NaN t has no distance in ulps (the verdicts already counted it as wrong), and JSON has no
    // infinity.
    std::vector<double> ulps;
    for (const double u : score.t_ulps) {
        if (std::isfinite(u)) ulps.push_back(u);
    }
    const UlpSummary summary = summarize_ulps(ulps);
    point.t_ulps_median = summary.median;
    point.t_ulps_p99 = summary.p99;
    point.t_ulps_max = summary.max;
    return point;
}

}  // namespace

ParetoFamily measure_pareto_family(const CaseFamily& family,
                                   const std::vector<ParetoMethod>& methods,
                                   const ParetoTiming& timing) {
    ParetoFamily result;
    result.name = family.name;
    result.description = family.description;
    result.cases = family.cases.size();
    for (const ParetoMethod& entry : methods) {
        const TimedPairs pairs = pairs_for(entry.method, family);
        if (pairs.rays.empty()) continue;
        ParetoPoint point = score_point(entry, family);
        point.mrays_per_second = tests_per_microsecond(entry.method, pairs, timing);
        result.points.push_back(point);
    }
    return result;
}

std::string pareto_table(const std::vector<ParetoFamily>& families) {
    MarkdownTable table({"family", "method", "precision", "cases", "Mrays/s", "false hits",
                         "false misses", "wrong %", "t ulps median", "p99", "max"});
    for (const ParetoFamily& family : families) {
        for (const ParetoPoint& p : family.points) {
            table.add_row({family.name, p.label, p.precision, grouped(p.cases),
                           three_digits(p.mrays_per_second), grouped(p.false_hits),
                           grouped(p.false_misses), fixed(100.0 * p.wrong_share(), 2),
                           ulp_text(p.t_ulps_median), ulp_text(p.t_ulps_p99),
                           ulp_text(p.t_ulps_max)});
        }
    }
    return table.text();
}

}  // namespace raystep
