// Stage 3's speed against error: the submission's intersect_triangle on rays through the shared
// edges of closed meshes, how often it is wrong (a leak is the error this family exists to show)
// and how fast, placed in the report on the chart `raystep-reference bench --pareto` draws for
// that family (docs/measurements/pareto.md). Reported, worth no points: which trade-off a
// student's renderer makes is theirs to choose.
//
// The speed is measured against the reference's intersect_triangle_cramer on the same pairs, in
// this run, both timed from outside their probes; the report turns the ratio into Mrays/s on the
// chart's own scale through the chart's Cramer point (grader/grade/speed_error_chart.h).

#include <algorithm>
#include <cmath>

#include "app/check/case_scoring.h"
#include "app/check/check_report.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/3_intersect/decide_cases.h"
#include "grading/3_intersect/intersect_calls.h"
#include "grading/3_intersect/stage3_families.h"

namespace raystep::grade {

namespace {

using probe::Json;

constexpr std::uint64_t kSeed = 0x5EED'5EED'2026;
// Leaks are a few percent of these rays for the lecture methods: 2,000 cases resolve that to
// half a percent.
constexpr std::size_t kCases = 2000;
// The timed pairs, the family's first as the bench takes them
// (studies/speed_error/pareto_study.cpp), each tested kPasses times: 10 million tests, a quarter
// of a second or more of the reference's Cramer, so that the sandbox's start-up time, which varies
// by tens of milliseconds from run to run and is subtracted, stays within a tenth of it: the
// chart's speed axis is logarithmic, and a tenth is a small step on it.
constexpr std::size_t kTimedPairs = 2048;
constexpr int kPasses = 5000;

const CaseFamily& decided_shared_edges() {
    static const CaseFamily family = [] {
        const Stage3Family* shared_edges = find_stage3_family(kSpeedErrorFamily);
        CaseFamily cases = generate_cases(*shared_edges, kSeed, kCases);
        decide_cases(cases, shared_edges->t_ulps);
        return cases;
    }();
    return family;
}

probe::TriangleWorkloadQuestion timed_pairs(const CaseFamily& family) {
    probe::TriangleWorkloadQuestion pairs;
    for (const RayCase& ray_case : family.cases) {
        for (const CasePrimitive& primitive : ray_case.primitives) {
            const auto* triangle = std::get_if<Triangle>(&primitive.shape);
            if (!triangle || pairs.primitives.triangles.size() == kTimedPairs) continue;
            pairs.rays.push_back(ray_case.ray);
            pairs.primitives.triangles.push_back(*triangle);
        }
    }
    return pairs;
}

CheckMeasure measure_speed_error(const GradingContext& context, const BuiltProbe& probe) {
    if (!probe.program) return not_compiled(probe);
    CheckMeasure measure;
    const CaseFamily& family = decided_shared_edges();
    Stage3Method method{"intersect_triangle", Stage3Method::Kind::triangle};

    // The errors, on every case
    const ProbeSession session = ask_probe(
        *probe.program, {probe::query(probe::stage3_cases_call, {method.name, family.cases})}, {});
    const ProbeAnswer& answer = session.answers[0];
    if (answer.kind == ProbeAnswer::Kind::not_implemented) {
        measure.outcome = Outcome::not_implemented;
        measure.summary = answer.message;
        return measure;
    }
    if (answer.kind != ProbeAnswer::Kind::result || answer.value.size() != family.cases.size()) {
        measure.outcome = Outcome::failed;
        measure.summary = "intersect_triangle did not answer the cases: " + answer_text(answer);
        return measure;
    }
    std::vector<CaseAnswer> answers;
    for (const Json& a : answer.value)
        answers.push_back(probe::case_answer_from(a));
    const MethodScore score = score_family(method, family, answers, 0);
    if (score.not_implemented) {
        measure.outcome = Outcome::not_implemented;
        measure.summary = score.not_implemented_message;
        return measure;
    }

    // The speed, against the reference's Cramer on the same pairs
    probe::TriangleWorkloadQuestion student_pairs = timed_pairs(family);
    student_pairs.method = "intersect_triangle";
    probe::TriangleWorkloadQuestion reference_pairs = student_pairs;
    reference_pairs.method = "intersect_triangle_cramer";
    const std::vector<WorkloadTime> timed = timed_workloads(
        {{*probe.program, probe::query(probe::triangle_workload_call, student_pairs)},
         {context.reference_probe, probe::query(probe::triangle_workload_call, reference_pairs)}},
        kPasses);
    const WorkloadTime& student = timed[0];
    const WorkloadTime& reference = timed[1];
    if (!student.answered || !reference.answered) {
        measure.outcome = Outcome::failed;
        measure.summary = !student.answered ? "intersect_triangle did not answer the timed workload"
                                            : "the reference did not answer the timed workload";
        return measure;
    }

    const double false_hits = static_cast<double>(score.count(Verdict::false_hit));
    const double false_misses =
        static_cast<double>(score.count(Verdict::false_miss) + score.count(Verdict::leak));
    // A NaN t has no distance in ulps (the verdicts already counted it as wrong), and the
    // report's JSON has no infinity.
    std::vector<double> ulps;
    for (const double u : score.t_ulps) {
        if (std::isfinite(u)) ulps.push_back(u);
    }
    const UlpSummary ulp_summary = summarize_ulps(ulps);
    const double speed = reference.seconds / student.seconds;
    measure.outcome = Outcome::passed;
    measure.fraction = 1.0;
    measure.metrics = {{kSpeedErrorCases, static_cast<double>(score.cases)},
                       {kSpeedErrorFalseHits, false_hits},
                       {kSpeedErrorFalseMisses, false_misses},
                       {kSpeedErrorUlpsMedian, ulp_summary.median},
                       {kSpeedErrorUlpsP99, ulp_summary.p99},
                       {kSpeedErrorAgainstCramer, speed}};
    char text[200];
    std::snprintf(text, sizeof text,
                  "intersect_triangle on %zu rays through shared edges: %.0f false misses (leaks "
                  "included), %.0f false hits; %.2f times the speed of the reference's Cramer",
                  score.cases, false_misses, false_hits, speed);
    measure.summary = text;
    return measure;
}

}  // namespace

CheckDefinition stage3_speed_error_check() {
    return {kSpeedErrorCheck, 3, "speed",
            "intersect_triangle's speed against its error on rays through shared edges, on the "
            "chart of docs/measurements/pareto.md (reported, no points)",
            measure_speed_error};
}

}  // namespace raystep::grade
