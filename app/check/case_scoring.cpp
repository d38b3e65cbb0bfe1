#include "app/check/case_scoring.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <variant>

#include <glm/geometric.hpp>

#include "app/check/case_file.h"
#include "app/check/case_format.h"

namespace raystep {

namespace {

// A reported normal passes as unit length when | |n| - 1 | is at most this or the expectation's
// normal_tolerance, whichever is larger. Normalizing in double precision leaves |n| within a few
// units of 2^-53 of 1; a normal that was never normalized, or was divided by the wrong length, is
// off by far more. The handout's sphere normal (P - C) / r is off 1 by the rounding of P - C over
// r, which on a small sphere far away exceeds 1e-9 but never the normal_tolerance, which bounds
// that same error: any n within normal_tolerance of a unit vector has | |n| - 1 | within it.
constexpr double kUnitLengthTolerance = 1e-9;

// What one case showed: the verdict and its reason, and what the family's score sums up.
struct CaseFindings {
    Verdict verdict = Verdict::pass;
    std::string detail;
    std::vector<double> t_ulps;
    std::size_t hits_at_t_zero = 0;
    double largest_t_error_at_zero = 0.0;
    std::size_t near_boundary_hits = 0;
    std::size_t near_boundary_misses = 0;
    bool exact_false_hit = false;
    bool exact_false_miss = false;

    // The enum lists the rules in the order in which they decide, so the smallest failing
    // verdict wins; among failures of one rule, the first found (the earliest primitive) explains.
    void fail(Verdict failed, std::string why) {
        if (verdict == Verdict::pass || static_cast<int>(failed) < static_cast<int>(verdict)) {
            verdict = failed;
            detail = std::move(why);
        }
    }
};

std::string label(const RayCase& ray_case, std::size_t k) {
    return "primitive " + std::to_string(k) + " (" + shape_name(ray_case.primitives[k].shape) + ")";
}

bool is_triangle(const CasePrimitive& primitive) {
    return std::holds_alternative<Triangle>(primitive.shape);
}

bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string barycentric_text(double beta, double gamma) {
    return "(" + exact_text(beta) + ", " + exact_text(gamma) + ")";
}

// The same primitive, bit for bit: any test gives both the same answer, so closest_hit's tie rule
// decides between them whatever the rounding.
bool same_shape(const CaseShape& a, const CaseShape& b) {
    if (a.index() != b.index()) return false;
    if (const auto* s = std::get_if<Sphere>(&a)) {
        const Sphere& other = std::get<Sphere>(b);
        return s->center == other.center && s->radius == other.radius;
    }
    if (const auto* t = std::get_if<Triangle>(&a)) {
        const Triangle& other = std::get<Triangle>(b);
        return t->p0 == other.p0 && t->p1 == other.p1 && t->p2 == other.p2;
    }
    const Plane& p = std::get<Plane>(a);
    const Plane& other = std::get<Plane>(b);
    return p.point == other.point && p.normal == other.normal;
}

// A primitive the closest hit may be on: an exact hit, or a near-boundary miss whose crossing
// point a correct test may report.
bool is_candidate(const Expectation& e) {
    return e.hit || (e.near_boundary && !std::isnan(e.t));
}

// The expected t and normal that a reported t is measured against: the expectation's own, or
// the alternative (a sphere's far root) when there is one and the reported t is nearer to it.
struct ExpectedPoint {
    double t;
    Vec3 normal;
};

ExpectedPoint expected_point(const Expectation& e, double reported_t) {
    if (!std::isnan(e.t_alternative) &&
        std::abs(reported_t - e.t_alternative) < std::abs(reported_t - e.t)) {
        return {e.t_alternative, e.normal_alternative};
    }
    return {e.t, e.normal};
}

// Rule 2: every number of a reported hit is finite.
void check_finite(const Hit& hit, bool triangle, const std::string& who, CaseFindings& findings) {
    const bool finite_barycentrics = std::isfinite(hit.beta) && std::isfinite(hit.gamma);
    if (std::isfinite(hit.t) && is_finite(hit.normal) && (!triangle || finite_barycentrics)) return;
    std::string got = "t = " + exact_text(hit.t) + ", normal " + exact_text(hit.normal);
    if (triangle) got += ", barycentrics " + barycentric_text(hit.beta, hit.gamma);
    findings.fail(Verdict::not_finite,
                  who + ": reported a hit with a value that is not finite: " + got);
}

// Rule 3's measurements of a reported hit: its t, its normal and a triangle's barycentrics, and
// the t error in ulps where the exact answer is a hit.
void check_measurements(const Expectation& e, const Hit& hit, bool triangle, const std::string& who,
                        CaseFindings& findings) {
    if (std::isnan(e.t)) return;
    const ExpectedPoint expected = expected_point(e, hit.t);

    // Each test is written as !(error <= tolerance), so that a NaN error fails it.
    if (!(std::abs(hit.t - expected.t) <= e.t_tolerance)) {
        findings.fail(Verdict::wrong_t, who + ": expected t = " + exact_text(expected.t) +
                                            " within " + exact_text(e.t_tolerance) +
                                            ", got t = " + exact_text(hit.t) + ", off by " +
                                            exact_text(hit.t - expected.t));
    }
    const double length = glm::length(hit.normal);
    if (!(std::abs(length - 1.0) <= std::max(kUnitLengthTolerance, e.normal_tolerance))) {
        findings.fail(Verdict::wrong_normal, who + ": the normal " + exact_text(hit.normal) +
                                                 " has length " + exact_text(length) + ", not 1");
    } else if (!(glm::length(hit.normal - expected.normal) <= e.normal_tolerance)) {
        findings.fail(Verdict::wrong_normal,
                      who + ": expected the normal " + exact_text(expected.normal) + " within " +
                          exact_text(e.normal_tolerance) + ", got " + exact_text(hit.normal));
    }
    if (triangle && !std::isnan(e.beta) &&
        !(std::abs(hit.beta - e.beta) <= e.barycentric_tolerance &&
          std::abs(hit.gamma - e.gamma) <= e.barycentric_tolerance)) {
        findings.fail(
            Verdict::wrong_barycentrics,
            who + ": expected barycentrics (beta, gamma) = " + barycentric_text(e.beta, e.gamma) +
                " within " + exact_text(e.barycentric_tolerance) + ", got " +
                barycentric_text(hit.beta, hit.gamma));
    }
    if (!e.hit) return;
    if (std::abs(expected.t) <= e.t_tolerance) {
        ++findings.hits_at_t_zero;
        findings.largest_t_error_at_zero =
            std::max(findings.largest_t_error_at_zero, std::abs(hit.t - expected.t));
    } else {
        findings.t_ulps.push_back(ulp_distance(hit.t, expected.t));
    }
}

// Rules 2 to 4 for a test of one kind of primitive.
void judge_primitive_tests(const Stage3Method& method, const RayCase& ray_case,
                           const CaseAnswer& answer, CaseFindings& findings) {
    std::optional<std::size_t> first_exact_hit;
    bool reported_a_hit = false;
    for (std::size_t k = 0; k < ray_case.primitives.size(); ++k) {
        const CasePrimitive& primitive = ray_case.primitives[k];
        if (!applies_to(method, primitive.shape)) continue;
        const Expectation& e = primitive.expected;
        // The answer may come from untrusted code: a list too short reads as misses.
        const std::optional<Hit> hit = k < answer.hits.size() ? answer.hits[k] : std::nullopt;
        const std::string who = label(ray_case, k);
        const bool triangle = is_triangle(primitive);

        if (hit) {
            reported_a_hit = true;
            check_finite(*hit, triangle, who, findings);
        }
        if (e.hit && !first_exact_hit) first_exact_hit = k;

        // The decision: near a boundary either answer passes.
        if (e.near_boundary) {
            ++(hit ? findings.near_boundary_hits : findings.near_boundary_misses);
        } else if (e.hit && !hit) {
            findings.fail(Verdict::false_miss,
                          who + ": expected a hit at t = " + exact_text(e.t) + ", got a miss");
        } else if (!e.hit && hit) {
            findings.fail(Verdict::false_hit,
                          who + ": expected a miss, got a hit at t = " + exact_text(hit->t));
        }
        if (hit) check_measurements(e, *hit, triangle, who, findings);
    }

    // Against the exact answer, near a boundary or not: what the ray meets, not which neighbour
    // of an edge takes it.
    findings.exact_false_hit = reported_a_hit && !first_exact_hit;
    findings.exact_false_miss = !reported_a_hit && first_exact_hit;

    // Rule 4: near an edge each neighbour may miss, but not all of them.
    if (ray_case.watertight && first_exact_hit && !reported_a_hit) {
        findings.fail(
            Verdict::leak,
            "the ray meets the closed mesh (" + label(ray_case, *first_exact_hit) +
                " at t = " + exact_text(ray_case.primitives[*first_exact_hit].expected.t) +
                ") and no primitive reported a hit: the ray slipped through");
    }
}

// Rule 5: closest_hit.
void judge_closest_hit(const RayCase& ray_case, const CaseAnswer& answer, CaseFindings& findings) {
    const std::vector<CasePrimitive>& primitives = ray_case.primitives;

    // A miss passes only where every exact hit is near a boundary and the mesh cannot leak.
    if (!answer.closest_hit) {
        std::optional<std::size_t> nearest_definite_hit;
        std::optional<std::size_t> first_exact_hit;
        bool any_candidate = false;
        for (std::size_t k = 0; k < primitives.size(); ++k) {
            const Expectation& e = primitives[k].expected;
            any_candidate = any_candidate || is_candidate(e);
            if (e.hit && !first_exact_hit) first_exact_hit = k;
            if (e.hit && !e.near_boundary &&
                (!nearest_definite_hit || e.t < primitives[*nearest_definite_hit].expected.t)) {
                nearest_definite_hit = k;
            }
        }
        if (nearest_definite_hit) {
            findings.fail(
                Verdict::false_miss,
                "expected the closest hit on " + label(ray_case, *nearest_definite_hit) +
                    " at t = " + exact_text(primitives[*nearest_definite_hit].expected.t) +
                    ", got a miss");
        } else if (ray_case.watertight && first_exact_hit) {
            findings.fail(Verdict::leak,
                          "the ray meets the closed mesh (" + label(ray_case, *first_exact_hit) +
                              " at t = " + exact_text(primitives[*first_exact_hit].expected.t) +
                              ") and closest_hit reported a miss: the ray slipped through");
        } else if (any_candidate) {
            ++findings.near_boundary_misses;
        }
        findings.exact_false_miss = first_exact_hit.has_value();
        return;
    }

    const Hit& hit = *answer.closest_hit;
    const std::size_t k = answer.closest_primitive.value_or(primitives.size());
    if (k >= primitives.size()) {
        findings.fail(Verdict::false_hit, "closest_hit reported a hit at t = " + exact_text(hit.t) +
                                              " on a primitive the case does not have (it has " +
                                              std::to_string(primitives.size()) + ")");
        return;
    }
    const Expectation& e = primitives[k].expected;
    const std::string who = label(ray_case, k);
    const bool triangle = is_triangle(primitives[k]);
    check_finite(hit, triangle, who, findings);
    findings.exact_false_hit =
        std::none_of(primitives.begin(), primitives.end(),
                     [](const CasePrimitive& primitive) { return primitive.expected.hit; });
    if (!is_candidate(e)) {
        findings.fail(Verdict::false_hit,
                      who + ": expected a miss, got the closest hit at t = " + exact_text(hit.t));
        return;
    }
    if (e.near_boundary) ++findings.near_boundary_hits;
    check_measurements(e, hit, triangle, who, findings);

    // Ties go to the primitive first in closest_hit's order (spheres, triangles, planes, each in
    // list order: the variant's order, then the case's). A tie is decidable only where rounding
    // cannot break it: a copy of the chosen primitive, which every test answers alike, or an
    // exact hit at the same t where neither t may round (both tolerances zero).
    const auto first_in_order = [&](std::size_t j) {
        const std::size_t rank_j = primitives[j].shape.index();
        const std::size_t rank_k = primitives[k].shape.index();
        return rank_j < rank_k || (rank_j == rank_k && j < k);
    };
    for (std::size_t j = 0; j < primitives.size(); ++j) {
        if (j == k || !first_in_order(j)) continue;
        const Expectation& other = primitives[j].expected;
        const bool copy = same_shape(primitives[j].shape, primitives[k].shape);
        const bool exact_tie = e.hit && other.hit && !other.near_boundary && other.t == e.t &&
                               other.t_tolerance == 0.0 && e.t_tolerance == 0.0;
        if (copy || exact_tie) {
            findings.fail(Verdict::wrong_primitive,
                          "closest_hit chose " + who + ", but " + label(ray_case, j) +
                              " is hit at the same t and comes first in closest_hit's order "
                              "(spheres, triangles, planes, each in list order): ties go to the "
                              "first");
            return;
        }
    }

    // Another primitive is clearly nearer when even the latest t its hit may have is below the
    // earliest the chosen one may have. fmax skips a NaN alternative.
    for (std::size_t j = 0; j < primitives.size(); ++j) {
        const Expectation& other = primitives[j].expected;
        if (j == k || !other.hit || other.near_boundary) continue;
        if (std::fmax(other.t, other.t_alternative) + other.t_tolerance < hit.t - e.t_tolerance) {
            findings.fail(Verdict::wrong_primitive,
                          "closest_hit chose " + who + " at t = " + exact_text(hit.t) + ", but " +
                              label(ray_case, j) + " is hit nearer, at t = " + exact_text(other.t));
            break;
        }
    }
}

CaseFindings judge(const Stage3Method& method, const RayCase& ray_case, const CaseAnswer& answer) {
    CaseFindings findings;
    // Rule 1: an exception leaves nothing to judge.
    if (answer.not_implemented || !answer.error.empty()) {
        findings.verdict = Verdict::threw;
        findings.detail = method.name + " threw: " + answer.error;
        return findings;
    }
    if (method.kind == Stage3Method::Kind::closest) {
        judge_closest_hit(ray_case, answer, findings);
    } else {
        judge_primitive_tests(method, ray_case, answer, findings);
    }
    return findings;
}

}  // namespace

double ulp_distance(double a, double b) {
    if (std::isnan(a) || std::isnan(b)) return std::numeric_limits<double>::infinity();
    // The bits of a non-negative double, read as an integer, grow with the double. A negative
    // double has the sign bit set and the bits of its magnitude: reflecting it below zero makes
    // the integers grow with the doubles everywhere, with -0 and +0 both at 0.
    const auto ordered = [](double x) {
        std::int64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
    };
    const std::int64_t x = ordered(a);
    const std::int64_t y = ordered(b);
    // From -max to +max the difference exceeds INT64_MAX, never 2^64: unsigned arithmetic
    // holds it exactly.
    const std::uint64_t distance =
        x > y ? static_cast<std::uint64_t>(x) - static_cast<std::uint64_t>(y)
              : static_cast<std::uint64_t>(y) - static_cast<std::uint64_t>(x);
    return static_cast<double>(distance);
}

Verdict score_case(const Stage3Method& method, const RayCase& ray_case, const CaseAnswer& answer,
                   std::string& detail) {
    CaseFindings findings = judge(method, ray_case, answer);
    detail = std::move(findings.detail);
    return findings.verdict;
}

MethodScore score_family(const Stage3Method& method, const CaseFamily& family,
                         const std::vector<CaseAnswer>& answers, std::size_t keep_counterexamples) {
    if (answers.size() != family.cases.size()) {
        throw std::invalid_argument("score_family: " + std::to_string(answers.size()) +
                                    " answers for the " + std::to_string(family.cases.size()) +
                                    " cases of family " + family.name);
    }
    MethodScore score;
    score.method = method.name;
    score.family = family.name;
    for (std::size_t k = 0; k < family.cases.size(); ++k) {
        const RayCase& ray_case = family.cases[k];
        const bool applies = std::any_of(
            ray_case.primitives.begin(), ray_case.primitives.end(),
            [&](const CasePrimitive& primitive) { return applies_to(method, primitive.shape); });
        if (!applies) continue;

        const CaseAnswer& answer = answers[k];
        if (answer.not_implemented) {
            MethodScore stub;
            stub.method = method.name;
            stub.family = family.name;
            stub.not_implemented = true;
            stub.not_implemented_message = answer.error;
            return stub;
        }

        CaseFindings findings = judge(method, ray_case, answer);
        ++score.cases;
        ++score.counts[static_cast<int>(findings.verdict)];
        if (findings.verdict == Verdict::pass) {
            ++score.passed;
        } else if (score.counterexamples.size() < keep_counterexamples) {
            score.counterexamples.push_back({ray_case.index, findings.verdict,
                                             std::move(findings.detail), case_text(ray_case)});
        }
        score.t_ulps.insert(score.t_ulps.end(), findings.t_ulps.begin(), findings.t_ulps.end());
        score.hits_at_t_zero += findings.hits_at_t_zero;
        score.largest_t_error_at_zero =
            std::max(score.largest_t_error_at_zero, findings.largest_t_error_at_zero);
        score.near_boundary_hits += findings.near_boundary_hits;
        score.near_boundary_misses += findings.near_boundary_misses;
        score.exact_false_hits += findings.exact_false_hit ? 1 : 0;
        score.exact_false_misses += findings.exact_false_miss ? 1 : 0;
    }
    return score;
}

const char* verdict_name(Verdict verdict) {
    switch (verdict) {
        case Verdict::pass:
            return "pass";
        case Verdict::not_finite:
            return "not finite";
        case Verdict::false_hit:
            return "false hit";
        case Verdict::false_miss:
            return "false miss";
        case Verdict::leak:
            return "leak";
        case Verdict::wrong_t:
            return "wrong t";
        case Verdict::wrong_normal:
            return "wrong normal";
        case Verdict::wrong_barycentrics:
            return "wrong barycentrics";
        case Verdict::wrong_primitive:
            return "wrong primitive";
        case Verdict::threw:
            return "threw";
    }
    return "unknown verdict";
}

}  // namespace raystep
