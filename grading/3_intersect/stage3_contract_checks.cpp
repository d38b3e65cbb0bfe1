// Stage 3's contract edges, each a check with points of its own: both ends of [t_min, t_max] in
// the range and a step beyond either out of it, ties to the primitive listed first, a ray lying in
// a plane a miss, degenerate input a miss and never a NaN or a throw. A sentence broken in one
// function shows in few cases, and scored by the share of cases it would cost a few hundredths of
// a point; so each check is asked of the functions of intersect.h whose sentence it is and scored
// by the share of them that keep it on every case (function_share.h), and the rubric gives a check
// nothing unless all of them do. A right test answers every case: the range ends, ties and rays in
// a plane are exact (grading/3_intersect/dyadic_hits.h), and a degenerate triangle is a miss that
// no rounding excuses.
//
// Each check draws its cases anew from the grading seed (statistics_seed(), raystep-grade's
// --seed) after a few hand-picked ones, so that `raystep-grade seeds` measures how often a check
// catches its bug and how often it fails a right submission
// (docs/measurements/stage3-check-power.md).

#include "app/check/stage3_methods.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/grade/checks/statistics_seed.h"
#include "grading/3_intersect/decide_cases.h"
#include "grading/3_intersect/function_share.h"
#include "grading/3_intersect/hit_miss_share.h"
#include "grading/3_intersect/stage3_contract_cases.h"
#include "grading/3_intersect/stage3_contract_edges.h"

namespace raystep::grade {

namespace {

// Drawn cases per check, beside the hand-picked ones. Of 24 degenerate cases, 15 are collinear
// triangles drawn to trip a solve without a zero-normal test: 9 Cramer's rule, 6 Moller-Trumbore.
constexpr std::size_t kDrawnCases = 24;

bool every_function(const Stage3Method&) {
    return true;
}

bool closest_hit_alone(const Stage3Method& method) {
    return method.kind == Stage3Method::Kind::closest;
}

bool all_but_spheres(const Stage3Method& method) {
    return method.kind != Stage3Method::Kind::sphere;
}

struct ContractEdge {
    const char* id;
    const char* name;
    CaseFamily (*family)(std::uint64_t seed, std::size_t count);
    /// Every number exact: no rounding may move an answer (tighten_exact_family)
    bool exact;
    /// The functions whose sentence it is: a check asks no other (the sphere test on a tie's
    /// sphere would check its t, not the tie)
    bool (*asks)(const Stage3Method&);
    /// The sentence asks only for misses: a function that never hits would keep it
    bool misses_only;
};

const ContractEdge kEdges[] = {
    {"stage3.contract.range_ends",
     "hits at t_min and at t_max are in the range and hits a step beyond them are not, in every "
     "function",
     range_end_family, true, every_function, false},
    {"stage3.contract.ties",
     "closest_hit gives a tie to the primitive listed first: spheres, triangles, planes",
     tie_family, true, closest_hit_alone, false},
    {"stage3.contract.ray_in_plane",
     "a ray lying in a plane, or in a triangle's plane, misses it, in every plane and triangle "
     "test and closest_hit",
     in_plane_family, true, all_but_spheres, true},
    {"stage3.contract.degenerate",
     "collinear triangles, repeated vertices, zero directions, radii and normals: a miss, never "
     "a NaN or a throw",
     degenerate_family, false, every_function, true},
};

CheckMeasure measure_edge(const ContractEdge& edge, const GradingContext& context,
                          const BuiltProbe& probe) {
    CaseFamily family = edge.family(statistics_seed(), kDrawnCases);
    decide_cases(family);
    if (edge.exact) tighten_exact_family(family);

    // A sentence of misses is kept only by a function that also hits where it must: each function
    // the check asks answers the range ends' hits too (exact, so no rounding excuses a miss), and
    // one that never hits, a stub that returns nothing, keeps no sentence.
    CaseFamily must_hit;
    if (edge.misses_only) {
        must_hit = range_end_family(statistics_seed(), kDrawnCases);
        decide_cases(must_hit);
        tighten_exact_family(must_hit);
    }

    // Every function the family reaches, each case counted against the function it asks
    FunctionShare share;
    std::size_t leaks = 0;  // no case is watertight
    std::vector<ProbeCase> cases;
    for (const Stage3Method& method : stage3_methods()) {
        if (!edge.asks(method)) continue;
        for (ProbeCase& probe_case : method_cases({method}, {family}, leaks))
            cases.push_back(share.counted(std::move(probe_case), method.name));
        for (const RayCase& ray_case : must_hit.cases) {
            if (case_kind(method, ray_case) != CaseKind::hit) continue;
            cases.push_back(
                share.counted(method_case(method, must_hit, ray_case, leaks), method.name));
        }
    }
    CheckMeasure measure = run_cases(context, edge.id, probe, cases);
    share.score(measure);
    return measure;
}

}  // namespace

std::vector<CheckDefinition> stage3_contract_checks() {
    std::vector<CheckDefinition> checks;
    for (const ContractEdge& edge : kEdges) {
        checks.push_back({edge.id, 3, "unit", edge.name,
                          [&edge](const GradingContext& context, const BuiltProbe& probe) {
                              return measure_edge(edge, context, probe);
                          }});
    }
    return checks;
}

}  // namespace raystep::grade
