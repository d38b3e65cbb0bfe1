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

#include "core/check/case_file.h"
#include "core/check/case_scoring.h"
#include "grader/families/stage3_families.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/oracle/decide_cases.h"

namespace raystep::grade {

namespace {

constexpr std::uint64_t kHiddenSeed = 0x5EED'7A11'2026;
constexpr std::size_t kCasesPerFamily = 40;
constexpr std::size_t kCounterexamples = 5;

// The contract on hand-picked cases, which random families reach seldom: a ray's [t_min, t_max]
// cutting a hit off on either side, triangles in the coordinate planes (the projection method's
// choice of axis), and several primitives at once, the nearest not the first in closest_hit's
// order (spheres, triangles, planes).
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
        for (const CaseShape& shape : shapes) c.primitives.push_back({shape, {}});
        return c;
    };
    CaseFamily family{"contract", 0, "t ranges, triangles in coordinate planes, nearest of several", {
        one({{0.3, -0.2, 5}, {0, 0, -1}}, in_z),
        one({{0.3, -0.2, 5}, {0, 0, -1}, 6.0, inf}, in_z),   // before t_min
        one({{0.3, -0.2, 5}, {0, 0, -1}, 0.0, 4.0}, in_z),   // beyond t_max
        one({{0.3, -0.2, 5}, {0, 0, 1}}, in_z),              // behind the origin
        one({{3, 0, 5}, {0, 0, -1}}, in_z),
        one({{-0.2, 0.5, 5}, {0.05, -0.1, -1}}, in_z),
        one({{5, 0.1, 0.1}, {-1, 0, 0}}, in_x),
        one({{5, 0.9, 0.9}, {-1, 0, 0}}, in_x),
        one({{-4, -0.3, -0.5}, {1, 0.02, 0.03}}, in_x),
        one({{0.1, 2, -0.2}, {0, -1, 0}}, in_y),
        one({{0.9, 2, 0.9}, {0, -1, 0}}, in_y),
        one({{0, 0, -5}, {0, 0, 1}}, unit),
        one({{0, 0, -5}, {0, 0, 1}, 0.0, 3.0}, unit),        // both roots beyond t_max
        one({{0, 0, -5}, {0, 0, 1}, 4.5, inf}, unit),        // the near root before t_min
        one({{0, 0, -5}, {0, 0, 1}, 6.5, inf}, unit),        // both before t_min
        one({{0, 0, 5}, {0, 0, 1}}, unit),                   // behind the origin
        one({{0, 0, 5}, {0, 0, -1}, 0.0, 3.0}, at_z3),
        one({{0, 0, 5}, {0, 0, -1}, 0.0, 1.0}, at_z3),       // beyond t_max
        one({{0, 0, 5}, {0, 0, -1}, 2.5, inf}, at_z3),       // before t_min
        many({{0, 0, -5}, {0, 0, 1}}, {far_sphere, in_z, at_z3}),
        many({{0.1, 0.1, 20}, {0, 0, -1}}, {far_sphere, in_z, at_z15}),
        many({{0.1, 0.1, 20}, {0, 0, -1}, 0.0, 8.0}, {far_sphere, in_z, at_z15}),
        many({{0.1, 0.1, 20}, {0, 0, -1}, 6.0, inf}, {far_sphere, in_z, at_z15}),
        many({{0.1, 0.1, 20}, {0, 0, -1}, 12.0, inf}, {far_sphere, in_z, at_z15}),
    }};
    for (std::size_t k = 0; k < family.cases.size(); ++k) family.cases[k].index = k;
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

// Each method on each family it applies to, one query per pair, scored case by case.
CheckMeasure measure_methods(const GradingContext& context, const BuiltProbe& probe,
                             const std::vector<Stage3Method>& methods,
                             const std::vector<CaseFamily>& families, const std::string& id) {
    std::vector<ProbeQuery> queries;
    std::vector<std::pair<const Stage3Method*, const CaseFamily*>> asked;
    for (const Stage3Method& method : methods) {
        for (const CaseFamily& family : families) {
            probe::Json questions = probe::Json::array();
            bool applies = false;
            for (const RayCase& c : family.cases) {
                questions.push_back(probe::case_question(c));
                for (const CasePrimitive& p : c.primitives) applies = applies || applies_to(method, p.shape);
            }
            if (!applies) continue;
            queries.push_back({"stage3_cases", {{"method", method.name}, {"cases", questions}}});
            asked.push_back({&method, &family});
        }
    }
    // One query per family: each judged case by case, below, rather than as a whole.
    std::vector<ProbeCase> cases;
    std::size_t passed = 0;
    std::size_t leaks = 0;
    std::size_t applicable = 0;  // a family may mix shapes: only the method's own are its cases
    std::vector<Counterexample> counterexamples;
    for (std::size_t k = 0; k < queries.size(); ++k) {
        const auto [method_ptr, family_ptr] = asked[k];
        cases.push_back({method_ptr->name + " on " + family_ptr->name, queries[k],
                         [&, k, method_ptr = method_ptr, family_ptr = family_ptr](const ProbeAnswer& answer) {
            const Stage3Method& method = *method_ptr;
            const CaseFamily& f = *family_ptr;
            if (answer.kind != ProbeAnswer::Kind::result) return wrong("answers", "");
            std::vector<CaseAnswer> answers;
            for (const probe::Json& a : answer.value) answers.push_back(probe::case_answer_from(a));
            if (answers.size() != f.cases.size()) return wrong(std::to_string(f.cases.size()) + " answers",
                                                                std::to_string(answers.size()));
            const MethodScore score = score_family(method, f, answers, kCounterexamples);
            leaks += score.count(Verdict::leak);
            passed += score.passed + score.count(Verdict::leak);
            applicable += score.cases;
            for (const raystep::Counterexample& c : score.counterexamples) {
                if (c.verdict == Verdict::leak || counterexamples.size() >= kCounterexamples) continue;
                counterexamples.push_back({method.name + " on " + f.name + " case " +
                                               std::to_string(c.case_index) + "\n" + c.text,
                                           "", std::string(verdict_name(c.verdict)) + ": " + c.detail,
                                           context.reproduce + " --check " + id + " --case " +
                                               std::to_string(k)});
            }
            return score.passed + score.count(Verdict::leak) == score.cases
                       ? right()
                       : wrong("every case right", "");
        }});
    }
    CheckMeasure measure = run_cases(context, id, probe, cases);
    if (measure.outcome == Outcome::did_not_compile || measure.outcome == Outcome::not_implemented) {
        return measure;
    }
    measure.counterexamples = counterexamples;
    measure.fraction = applicable == 0 ? 0.0 : static_cast<double>(passed) / applicable;
    measure.metrics = {{"cases", static_cast<double>(applicable)},
                       {"passed", static_cast<double>(passed)},
                       {"leaks (not failed)", static_cast<double>(leaks)}};
    measure.summary = std::to_string(passed) + " of " + std::to_string(applicable) + " cases right" +
                      (methods.size() > 1 ? " over " + std::to_string(methods.size()) + " functions"
                                          : " in " + std::to_string(asked.size()) + " families") +
                      (leaks ? " (" + std::to_string(leaks) + " leaks at shared edges, not failed)" : "") +
                      (measure.outcome == Outcome::crashed || measure.outcome == Outcome::timed_out
                           ? "; " + measure.details
                           : "");
    return measure;
}

}  // namespace

std::vector<CheckDefinition> stage3_checks() {
    std::vector<CheckDefinition> checks;
    for (const Stage3Method& method : stage3_methods()) {
        const std::string id = "stage3.oracle." + method.name;
        checks.push_back({id, 3, "oracle",
                          method.name + " on every hard-case family, against the exact oracle",
                          [method, id](const GradingContext& context, const BuiltProbe& probe) {
                              return measure_methods(context, probe, {method}, decided_families(), id);
                          }});
    }
    checks.push_back({"stage3.hidden", 3, "unit",
                      "every function on t ranges, triangles in coordinate planes and the nearest of several",
                      [](const GradingContext& context, const BuiltProbe& probe) {
                          return measure_methods(context, probe, stage3_methods(), decided_contract(),
                                                 "stage3.hidden");
                      }});
    checks.push_back(stage3_speed_error_check());
    return checks;
}

}  // namespace raystep::grade
