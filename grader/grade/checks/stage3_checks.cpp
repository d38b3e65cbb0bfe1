// Stage 3 checks: every intersection function on the hard-case families (grader/families) and on
// hand-picked cases of the contract,
// decided by the exact oracle (grader/oracle), scored as `raystep check` scores them
// (core/check/case_scoring.h). The seeds are the grader's own, not the public case files': a
// submission is graded on cases it has not seen.
//
// A leak (a ray through a shared edge that no triangle of the mesh reports) is counted and
// reported but not failed: stage 3's contract asks for the three lecture methods, which leak by
// design (docs/measurements/stage3-study.md), and intersect_triangle may be any of them.

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/check/case_file.h"
#include "core/check/case_scoring.h"
#include "grader/families/stage3_families.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/oracle/decide_cases.h"

namespace raystep::grade {

namespace {

constexpr std::uint64_t kHiddenSeed = 0x5EED'7A11'2026;
constexpr std::size_t kCasesPerFamily = 40;

// The contract on hand-picked cases, which random families reach seldom: a ray's [t_min, t_max]
// cutting a hit off on either side, triangles in the coordinate planes (the projection method's
// choice of axis), several primitives at once, the nearest not the first in closest_hit's
// order (spheres, triangles, planes), copies of one primitive, a tie that must go to the
// first, and slivers whose double cross product is not zero though an edge's inward normal
// rounds to zero (the half-spaces method's 0 / 0 barycentric).
CaseFamily contract_family() {
    const double inf = HUGE_VAL;
    const Triangle in_z{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    const Triangle in_x{{2, -1, -1}, {2, 1, -1}, {2, 0, 1}};
    const Triangle in_y{{-1, -3, -1}, {0, -3, 1}, {1, -3, -1}};
    const Sphere unit{{0, 0, 0}, 1};
    const Sphere far_sphere{{0, 0, 10}, 1};
    const Plane at_z3{{0, 0, 3}, {0, 0, 1}};
    const Plane at_z15{{0, 0, 15}, {0, 0, -1}};
    const auto one = [](const Ray& ray, const CaseShape& shape) {
        return RayCase{0, ray, {CasePrimitive{shape, {}}}, false};
    };
    const auto many = [](const Ray& ray, const std::vector<CaseShape>& shapes) {
        RayCase c{0, ray, {}, false};
        for (const CaseShape& shape : shapes)
            c.primitives.push_back({shape, {}});
        return c;
    };
    CaseFamily family{
        "contract",
        0,
        "t ranges, triangles in coordinate planes, nearest of several",
        {
            one({{0.3, -0.2, 5}, {0, 0, -1}}, in_z),
            one({{0.3, -0.2, 5}, {0, 0, -1}, 6.0, inf}, in_z),  // before t_min
            one({{0.3, -0.2, 5}, {0, 0, -1}, 0.0, 4.0}, in_z),  // beyond t_max
            one({{0.3, -0.2, 5}, {0, 0, 1}}, in_z),             // behind the origin
            one({{3, 0, 5}, {0, 0, -1}}, in_z),
            one({{-0.2, 0.5, 5}, {0.05, -0.1, -1}}, in_z),
            one({{5, 0.1, 0.1}, {-1, 0, 0}}, in_x),
            one({{5, 0.9, 0.9}, {-1, 0, 0}}, in_x),
            one({{-4, -0.3, -0.5}, {1, 0.02, 0.03}}, in_x),
            one({{0.1, 2, -0.2}, {0, -1, 0}}, in_y),
            one({{0.9, 2, 0.9}, {0, -1, 0}}, in_y),
            one({{0, 0, -5}, {0, 0, 1}}, unit),
            one({{0, 0, -5}, {0, 0, 1}, 0.0, 3.0}, unit),  // both roots beyond t_max
            one({{0, 0, -5}, {0, 0, 1}, 4.5, inf}, unit),  // the near root before t_min
            one({{0, 0, -5}, {0, 0, 1}, 6.5, inf}, unit),  // both before t_min
            one({{0, 0, 5}, {0, 0, 1}}, unit),             // behind the origin
            one({{0, 0, 5}, {0, 0, -1}, 0.0, 3.0}, at_z3),
            one({{0, 0, 5}, {0, 0, -1}, 0.0, 1.0}, at_z3),  // beyond t_max
            one({{0, 0, 5}, {0, 0, -1}, 2.5, inf}, at_z3),  // before t_min
            many({{0, 0, -5}, {0, 0, 1}}, {far_sphere, in_z, at_z3}),
            many({{0.1, 0.1, 20}, {0, 0, -1}}, {far_sphere, in_z, at_z15}),
            many({{0.1, 0.1, 20}, {0, 0, -1}, 0.0, 8.0}, {far_sphere, in_z, at_z15}),
            many({{0.1, 0.1, 20}, {0, 0, -1}, 6.0, inf}, {far_sphere, in_z, at_z15}),
            many({{0.1, 0.1, 20}, {0, 0, -1}, 12.0, inf}, {far_sphere, in_z, at_z15}),
            many({{0, 0, -5}, {0, 0, 1}}, {unit, unit}),  // ties
            many({{0.3, -0.2, 5}, {0, 0, -1}}, {in_z, in_z, in_z}),
            many({{0, 0, 5}, {0, 0, -1}}, {at_z3, at_z3}),
            many({{0.1, 0.1, -5}, {0, 0, 1}}, {far_sphere, unit, in_z, unit, in_z}),
            one({{1.0275703435596424, 0.78125, 3.2150703435596424},
                 {-0.7071067811865475, -0.0, -0.7071067811865475}},
                Triangle{{-0.875, 0.625, 0.875}, {-1.3125, 0.9374999999999999, 1.3125}, {0, 0, 0}}),
            one({{-0.6853907864998738, -0.28125, 3.0582815729997477},
                 {0.4472135954999579, -0.0, -0.8944271909999159}},
                Triangle{{0.875, -0.375, 0.5},
                         {0.4375, -0.18749999999999997, 0.24999999999999997},
                         {0, 0, 0}}),
        }};
    for (std::size_t k = 0; k < family.cases.size(); ++k)
        family.cases[k].index = k;
    return family;
}

const std::vector<CaseFamily>& decided_contract() {
    static const std::vector<CaseFamily> contract = [] {
        CaseFamily family = contract_family();
        decide_cases(family);
        return std::vector<CaseFamily>{std::move(family)};
    }();
    return contract;
}

// The families, decided once per grading run and shared by every method's check.
const std::vector<CaseFamily>& decided_families() {
    static const std::vector<CaseFamily> families = [] {
        std::vector<CaseFamily> all;
        for (const Stage3Family& family : stage3_families()) {
            CaseFamily cases = generate_cases(family, kHiddenSeed, kCasesPerFamily);
            decide_cases(cases, family.t_ulps);
            all.push_back(std::move(cases));
        }
        return all;
    }();
    return families;
}

// True when the case has a primitive the method tests (closest_hit: any).
bool applies(const Stage3Method& method, const RayCase& ray_case) {
    return std::any_of(ray_case.primitives.begin(), ray_case.primitives.end(),
                       [&](const CasePrimitive& p) { return applies_to(method, p.shape); });
}

// The case written out as a case file of its own and the `raystep check` command that runs the
// one function on it: what a student pastes into a shell in the student release.
std::string student_case_command(const Stage3Method& method, const CaseFamily& family,
                                 const RayCase& ray_case) {
    const std::string file = family.name + "-" + std::to_string(ray_case.index) + ".cases";
    std::ostringstream text;
    write_case_file(text, {CaseFamily{family.name, family.seed, family.description, {ray_case}}});
    return "cat > " + file + " <<'EOF'\n" + text.str() + "EOF\n" + kStudentRaystep +
           " check --stage 3 " + file + " --method " + method.name + " --case " +
           std::to_string(ray_case.index);
}

}  // namespace

ProbeCase method_case(const Stage3Method& method, const CaseFamily& family, const RayCase& ray_case,
                      std::size_t& leaks) {
    ProbeQuery query{
        "stage3_cases",
        {{"method", method.name}, {"cases", probe::Json::array({probe::case_question(ray_case)})}}};
    return {method.name + " on " + family.name + " case " + std::to_string(ray_case.index) + "\n" +
                case_text(ray_case),
            std::move(query),
            [&leaks, method, ray_case](const ProbeAnswer& answer) {
                if (answer.kind != ProbeAnswer::Kind::result) return wrong("an answer", "");
                if (!answer.value.is_array() || answer.value.size() != 1) {
                    return wrong("one answer", answer_text(answer));
                }
                const CaseAnswer got = probe::case_answer_from(answer.value[0]);
                if (got.not_implemented) return stub(got.error);
                std::string detail;
                const Verdict verdict = score_case(method, ray_case, got, detail);
                // A leak is counted and reported, not failed (see the top of this file).
                if (verdict == Verdict::leak) ++leaks;
                if (verdict == Verdict::pass || verdict == Verdict::leak) return right();
                return wrong("", std::string(verdict_name(verdict)) + ": " + detail);
            },
            student_case_command(method, family, ray_case)};
}

namespace {

// Each method on each case of each family that has a primitive it tests: one query per case, so
// that every case is in the denominator, answered or not, and has a number of its own to
// reproduce it by.
CheckMeasure measure_methods(const GradingContext& context, const BuiltProbe& probe,
                             const std::vector<Stage3Method>& methods,
                             const std::vector<CaseFamily>& families, const std::string& id) {
    std::size_t leaks = 0;
    std::vector<ProbeCase> cases;
    for (const Stage3Method& method : methods) {
        for (const CaseFamily& family : families) {
            for (const RayCase& ray_case : family.cases) {
                if (!applies(method, ray_case)) continue;
                cases.push_back(method_case(method, family, ray_case, leaks));
            }
        }
    }
    CheckMeasure measure = run_cases(context, id, probe, cases);
    if (leaks > 0) {
        measure.metrics["leaks (not failed)"] = static_cast<double>(leaks);
        if (measure.outcome == Outcome::passed || measure.outcome == Outcome::failed) {
            measure.summary += " (" + std::to_string(leaks) + " leaks at shared edges, not failed)";
        }
    }
    return measure;
}

}  // namespace

std::vector<CheckDefinition> stage3_checks() {
    std::vector<CheckDefinition> checks;
    for (const Stage3Method& method : stage3_methods()) {
        const std::string id = "stage3.oracle." + method.name;
        checks.push_back(
            {id, 3, "oracle", method.name + " on every hard-case family, against the exact oracle",
             [method, id](const GradingContext& context, const BuiltProbe& probe) {
                 return measure_methods(context, probe, {method}, decided_families(), id);
             }});
    }
    checks.push_back(
        {"stage3.hidden", 3, "unit",
         "every function on t ranges, triangles in coordinate planes and the nearest of several",
         [](const GradingContext& context, const BuiltProbe& probe) {
             return measure_methods(context, probe, stage3_methods(), decided_contract(),
                                    "stage3.hidden");
         }});
    checks.push_back(stage3_speed_error_check());
    return checks;
}

}  // namespace raystep::grade
