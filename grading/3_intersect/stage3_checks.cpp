// Stage 3 checks: every intersection function on the hard-case families (grading/3_intersect) and
// on hand-picked cases of the contract, decided by the exact oracle (grader/oracle), scored as
// `raystep check` scores them (app/check/case_scoring.h). The oracle checks' seeds are the
// grader's own, not the public case files': a submission is graded on cases it has not seen. Each
// function also earns points on the public case files, the check `raystep grade` runs on the
// student's laptop (grading/3_intersect/case_file_judges.h), scored by the same fraction. The
// contract's edges are checks of their own (stage3_contract_checks.cpp).
//
// A leak (a ray through a shared edge that no triangle of the mesh reports) is counted and
// reported but not failed: stage 3's contract asks for the three lecture methods, which leak by
// design (docs/measurements/stage3-study.md), and intersect_triangle may be any of them.

#include <algorithm>
#include <cmath>
#include <sstream>

#include "app/check/case_file.h"
#include "app/check/case_scoring.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/3_intersect/case_file_judges.h"
#include "grading/3_intersect/decide_cases.h"
#include "grading/3_intersect/hit_miss_share.h"
#include "grading/3_intersect/intersect_calls.h"
#include "grading/3_intersect/stage3_contract_cases.h"
#include "grading/3_intersect/stage3_families.h"

namespace raystep::grade {

namespace {

constexpr std::uint64_t kHiddenSeed = 0x5EED'7A11'2026;
constexpr std::size_t kCasesPerFamily = 40;

const std::vector<CaseFamily>& decided_contract() {
    static const std::vector<CaseFamily> contract = [] {
        CaseFamily family = contract_family();
        decide_cases(family);
        CaseFamily exact = exact_family();
        decide_cases(exact);
        tighten_exact_family(exact);
        return std::vector<CaseFamily>{std::move(family), std::move(exact)};
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
    ProbeQuery query = probe::query(probe::stage3_cases_call, {method.name, {ray_case}});
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

std::vector<ProbeCase> method_cases(const std::vector<Stage3Method>& methods,
                                    const std::vector<CaseFamily>& families, std::size_t& leaks) {
    std::vector<ProbeCase> cases;
    for (const Stage3Method& method : methods) {
        for (const CaseFamily& family : families) {
            for (const RayCase& ray_case : family.cases) {
                if (!applies(method, ray_case)) continue;
                cases.push_back(method_case(method, family, ray_case, leaks));
            }
        }
    }
    return cases;
}

namespace {

// Each method on each case of each family that has a primitive it tests, each case counted in
// `share` by what it asks, leaks counted and reported, not failed.
CheckMeasure measure_methods(const GradingContext& context, const BuiltProbe& probe,
                             const std::vector<Stage3Method>& methods,
                             const std::vector<CaseFamily>& families, const std::string& id,
                             HitMissShare& share) {
    std::size_t leaks = 0;
    std::vector<ProbeCase> cases;
    for (const Stage3Method& method : methods) {
        for (const CaseFamily& family : families) {
            for (const RayCase& ray_case : family.cases) {
                if (!applies(method, ray_case)) continue;
                cases.push_back(share.counted(method_case(method, family, ray_case, leaks),
                                              case_kind(method, ray_case)));
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

// Methods on the grader's hard-case families: the share of the cases right, but nothing for a
// function that answers fewer than half the cases of either kind right (hit_miss_share.h).
CheckMeasure measure_both_kinds(const GradingContext& context, const BuiltProbe& probe,
                                const std::vector<Stage3Method>& methods,
                                const std::vector<CaseFamily>& families, const std::string& id) {
    HitMissShare share;
    CheckMeasure measure = measure_methods(context, probe, methods, families, id, share);
    // One case asked again (--case N) is a reproduction, not a score
    if (!context.only_case) share.score(measure);
    return measure;
}

// The method on the public case files, scored as `raystep grade` scores it: the count right over
// the reference's count on the same files (stage3_cases_fraction), the reference run here, and
// nothing for a function that answers fewer than half the cases of either kind right.
CheckMeasure measure_public_cases(const GradingContext& context, const BuiltProbe& probe,
                                  const Stage3Method& method, const std::string& id) {
    // The grader's own tree's files, never the submission's copy.
    const std::vector<CaseFamily> families = stage3_public_families(context.grader_source);
    HitMissShare share;
    CheckMeasure measure = measure_methods(context, probe, {method}, families, id, share);
    // One case asked again (--case N) is a reproduction, not a score against the whole count.
    if (context.only_case || measure.grader_error || measure.outcome == Outcome::not_implemented ||
        measure.outcome == Outcome::did_not_compile) {
        return measure;
    }
    const std::size_t right = static_cast<std::size_t>(measure.metrics["passed"]);
    const std::size_t reference_right = stage3_cases_right(families).at(method.name);
    measure.fraction = stage3_cases_fraction(right, reference_right);
    if (measure.outcome == Outcome::failed && right >= reference_right) {
        measure.outcome = Outcome::passed;
    }
    measure.summary += "; the reference gets " + std::to_string(reference_right) + " right";
    share.score(measure);
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
                 return measure_both_kinds(context, probe, {method}, decided_families(), id);
             }});
    }
    for (const Stage3Method& method : stage3_methods()) {
        const std::string id = "stage3.cases." + method.name;
        checks.push_back({id, 3, "oracle", method.name + " on the public case files",
                          [method, id](const GradingContext& context, const BuiltProbe& probe) {
                              return measure_public_cases(context, probe, method, id);
                          }});
    }
    checks.push_back(
        {"stage3.hidden", 3, "unit",
         "every function on the contract: t ranges, edges, two sides, nearly parallel rays, the "
         "domain",
         [](const GradingContext& context, const BuiltProbe& probe) {
             return measure_both_kinds(context, probe, stage3_methods(), decided_contract(),
                                       "stage3.hidden");
         }});
    for (CheckDefinition& check : stage3_contract_checks())
        checks.push_back(std::move(check));
    checks.push_back(stage3_speed_error_check());
    return checks;
}

}  // namespace raystep::grade
