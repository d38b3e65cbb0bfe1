#include "grading/3_intersect/case_file_judges.h"

#include <algorithm>
#include <chrono>

#include "app/check/case_file.h"
#include "app/check/case_scoring.h"
#include "app/check/stage3_methods.h"
#include "app/grade/render_judge.h"

namespace raystep::grade {

namespace {

// One function over every family: its cases, those right (a leak counted right, as the grader's
// stage3 checks count it: the lecture methods leak at shared edges by design), the leaks among
// them, a stub's message, and its first failure that is not a leak.
struct MethodRun {
    std::size_t cases = 0;
    std::size_t passed = 0;
    std::size_t leaks = 0;
    KindTally kinds;
    std::string stub;
    std::vector<Counterexample> first_failure;
};

MethodRun run_over(const Stage3Method& method, const std::vector<CaseFamily>& families) {
    MethodRun run;
    for (const CaseFamily& family : families) {
        std::vector<CaseAnswer> answers;
        for (const RayCase& c : family.cases) {
            answers.push_back(run_method(method, c));
            const CaseKind kind = case_kind(method, c);
            if (kind == CaseKind::either) continue;
            std::string detail;
            const raystep::Verdict verdict = score_case(method, c, answers.back(), detail);
            run.kinds.count(kind,
                            verdict == raystep::Verdict::pass || verdict == raystep::Verdict::leak);
        }
        // Every counterexample kept, so that the first that is not a leak is among them.
        const MethodScore score = score_family(method, family, answers, family.cases.size());
        if (score.not_implemented) {
            run.stub = score.not_implemented_message;
            return run;
        }
        run.cases += score.cases;
        run.passed += score.passed + score.count(raystep::Verdict::leak);
        run.leaks += score.count(raystep::Verdict::leak);
        for (const raystep::Counterexample& example : score.counterexamples) {
            if (!run.first_failure.empty()) break;
            if (example.verdict == raystep::Verdict::leak) continue;
            const std::string index = std::to_string(example.case_index);
            run.first_failure.push_back(
                {"family " + family.name + ", case " + index + ": " + example.text, "pass",
                 std::string(verdict_name(example.verdict)) + ": " + example.detail, "",
                 std::string(kStudentBuildRaystep) + " check --stage 3 --family " + family.name +
                     " --method " + method.name + " --case " + index});
        }
    }
    return run;
}

}  // namespace

CaseKind case_kind(const Stage3Method& method, const RayCase& ray_case) {
    bool tested = false;
    bool hit = false;
    for (const CasePrimitive& primitive : ray_case.primitives) {
        if (!applies_to(method, primitive.shape)) continue;
        if (primitive.expected.near_boundary) return CaseKind::either;
        tested = true;
        hit = hit || primitive.expected.hit;
    }
    if (!tested) return CaseKind::either;
    return hit ? CaseKind::hit : CaseKind::miss;
}

void KindTally::count(CaseKind kind, bool right) {
    if (kind == CaseKind::either) return;
    (kind == CaseKind::hit ? hits : misses) += 1;
    if (right) (kind == CaseKind::hit ? hits_right : misses_right) += 1;
}

bool KindTally::both_kinds_kept() const {
    const auto kept = [](std::size_t right, std::size_t asked) {
        return asked == 0 ||
               static_cast<double>(right) >= kLeastShareOfEachKind * static_cast<double>(asked);
    };
    return kept(hits_right, hits) && kept(misses_right, misses);
}

std::string KindTally::shortfall() const {
    return "earns nothing: " + std::to_string(hits_right) + " of the " + std::to_string(hits) +
           " cases that must hit right, " + std::to_string(misses_right) + " of the " +
           std::to_string(misses) + " that must miss, where at least half of each must be";
}

std::vector<CaseFamily> stage3_public_families(const std::filesystem::path& root) {
    std::vector<CaseFamily> families;
    for (const auto& file : case_files_in(root / "stages" / "3_intersect" / "cases")) {
        for (CaseFamily& family : read_case_file(file))
            families.push_back(std::move(family));
    }
    return families;
}

std::map<std::string, std::size_t> stage3_cases_right(const std::vector<CaseFamily>& families) {
    std::map<std::string, std::size_t> right;
    for (const Stage3Method& method : stage3_methods()) {
        const MethodRun run = run_over(method, families);
        if (run.stub.empty()) right[method.name] = run.passed;
    }
    // intersect_triangle may be any of the three lecture methods (docs/stage3.md), so its count is
    // the lowest of theirs, as the grader's full mark for it is the loosest of theirs.
    for (const char* method : {"intersect_triangle_projection", "intersect_triangle_halfspaces",
                               "intersect_triangle_cramer"}) {
        const auto found = right.find(method);
        const auto triangle = right.find("intersect_triangle");
        if (found != right.end() && triangle != right.end())
            triangle->second = std::min(triangle->second, found->second);
    }
    return right;
}

double stage3_cases_fraction(std::size_t right, std::size_t reference_right) {
    if (right >= reference_right) return 1.0;
    return static_cast<double>(right) / static_cast<double>(reference_right);
}

std::vector<CheckResult> run_stage3_case_checks(const std::vector<CaseFamily>& families,
                                                const std::map<std::string, std::size_t>& reference,
                                                const Rubric& rubric) {
    std::vector<CheckResult> results;
    for (const Stage3Method& method : stage3_methods()) {
        const auto start = std::chrono::steady_clock::now();
        const std::string id = "stage3.cases." + method.name;
        const std::size_t reference_right = reference.at(method.name);
        const MethodRun run = run_over(method, families);
        const bool stub = !run.stub.empty();
        const bool kept = run.kinds.both_kinds_kept();
        const Outcome measured = stub                                    ? Outcome::not_implemented
                                 : kept && run.passed >= reference_right ? Outcome::passed
                                                                         : Outcome::failed;
        CheckResult result = scored_check(
            id, 3, "oracle", method.name + " on the public case files", rubric.entry(id), measured,
            kept ? stage3_cases_fraction(run.passed, reference_right) : 0.0);
        if (stub) {
            result.summary = run.stub;
        } else {
            result.summary = std::to_string(run.passed) + " of " + std::to_string(run.cases) +
                             " cases right (the reference: " + std::to_string(reference_right) +
                             ")";
            if (run.leaks > 0) {
                result.summary += "; " + std::to_string(run.leaks) +
                                  " of them leaks at shared edges, which the contract allows "
                                  "(docs/stage3.md)";
            }
            if (!kept) result.summary += "; " + run.kinds.shortfall();
            result.counterexamples = run.first_failure;
        }
        result.metrics["cases"] = static_cast<double>(run.cases);
        result.metrics["passed"] = static_cast<double>(run.passed);
        result.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        results.push_back(std::move(result));
    }
    return results;
}

}  // namespace raystep::grade
