// Stage 1 checks: the vector functions on hand-worked values (public and hidden), and against
// long-double arithmetic on random vectors of every magnitude.

#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "app/grade/value_judges.h"
#include "base/math/parallel_sine.h"
#include "base/math/portable_random.h"
#include "base/math/unit_roundoff.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/oracle/wide_vec.h"
#include "grading/1_vectors/vector_calls.h"

namespace raystep::grade {

namespace {

using probe::Json;

// The stage's public name, shared by the grader's check and the release's case file.
constexpr const char* kPublicName = "vector functions on hand-worked values";

// Every case of stage 1 is judged by a data judge (app/grade/value_judges.h): the public ones go
// into the student release as data, and the others are judged by the same code. A case names its
// call by the call's descriptor (grading/1_vectors/vector_calls.h), and its vectors are the call's
// arguments in order.
template <class Call>
PublicCase vector_case(const Call& call, const typename Call::QuestionType& args, Json judge) {
    const std::vector<Vec3> vectors =
        std::apply([](const auto&... v) { return std::vector<Vec3>{v...}; }, args);
    std::string code;
    for (const Vec3& v : vectors)
        code += (code.empty() ? "" : ", ") + cpp(v);
    const std::string name = call.name;
    return {name + vectors_text(vectors), probe::query(call, args), std::move(judge),
            name + "(" + code + ")"};
}

template <class Call>
PublicCase exact_vector(const Call& call, const typename Call::QuestionType& args, Vec3 expected,
                        double tolerance = 0.0) {
    return vector_case(call, args, near_vec3_judge(expected, tolerance));
}

template <class Call>
PublicCase exact_number(const Call& call, const typename Call::QuestionType& args, double expected,
                        double tolerance = 0.0) {
    return vector_case(call, args, near_number_judge(expected, tolerance));
}

template <class Call>
PublicCase throws_domain_error(const Call& call, const typename Call::QuestionType& args) {
    return vector_case(call, args, threw_judge("domain_error"));
}

// orthonormal_frame(a, b) against the expected frame, each component within `tolerance`.
PublicCase frame_case(const Vec3& a, const Vec3& b, const Vec3& u, const Vec3& v, const Vec3& w,
                      double tolerance = 4 * kUnitRoundoff) {
    return vector_case(probe::orthonormal_frame_call, {a, b}, frame_judge(u, v, w, tolerance));
}

std::vector<PublicCase> public_cases() {
    const double r2 = std::sqrt(0.5);
    return {
        exact_number(probe::dot_call, {{1, 2, 3}, {4, -5, 6}}, 12.0),
        exact_vector(probe::cross_call, {{1, 0, 0}, {0, 1, 0}}, {0, 0, 1}),
        exact_vector(probe::cross_call, {{0, 1, 0}, {1, 0, 0}}, {0, 0, -1}),
        exact_number(probe::length_call, {{3, 4, 0}}, 5.0),
        exact_number(probe::length_call, {{0, 0, 0}}, 0.0),
        exact_number(probe::length_call, {{3e200, 4e200, 0}}, 5e200, 4 * kUnitRoundoff * 5e200),
        exact_number(probe::length_call, {{3e-200, 4e-200, 0}}, 5e-200, 4 * kUnitRoundoff * 5e-200),
        exact_vector(probe::normalize_call, {{0, 3, 4}}, {0, 0.6, 0.8}, 2 * kUnitRoundoff),
        exact_vector(probe::normalize_call, {{1e-300, 0, 0}}, {1, 0, 0}, 2 * kUnitRoundoff),
        throws_domain_error(probe::normalize_call, {{0, 0, 0}}),
        exact_vector(probe::reflect_call, {{1, -1, 0}, {0, 1, 0}}, {1, 1, 0}),
        exact_vector(probe::project_onto_call, {{2, 3, 4}, {0, 2, 0}}, {0, 3, 0}),
        throws_domain_error(probe::project_onto_call, {{2, 3, 4}, {0, 0, 0}}),
        exact_vector(probe::perpendicular_to_call, {{2, 3, 4}, {0, 2, 0}}, {2, 0, 4}),
        frame_case({0, 0, 5}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}),
        frame_case({1, 0, 1}, {0, 1, 0}, {r2, 0, -r2}, {0, 1, 0}, {r2, 0, r2}),
        throws_domain_error(probe::orthonormal_frame_call, {{0, 0, 1}, {0, 0, 3}}),
    };
}

// v / |v| worked out in long double, then rounded: what normalize must return within a few ulps.
Vec3 wide_unit(const Vec3& v) {
    const Wide length = std::sqrt(Wide(v.x) * v.x + Wide(v.y) * v.y + Wide(v.z) * v.z);
    return {static_cast<double>(v.x / length), static_cast<double>(v.y / length),
            static_cast<double>(v.z / length)};
}

// The hidden ones: the contract's edge cases a student's own tests may not reach.
std::vector<PublicCase> hidden_cases() {
    const double inf = HUGE_VAL;
    const double r2 = std::sqrt(0.5);
    return {
        exact_number(probe::length_call, {{1e-320, 0, 0}}, 1e-320),
        exact_number(probe::length_call, {{1e300, 1e300, 1e300}}, std::sqrt(3.0) * 1e300,
                     4 * kUnitRoundoff * 2e300),
        throws_domain_error(probe::normalize_call, {{inf, 0, 0}}),
        throws_domain_error(probe::normalize_call, {{std::nan(""), 1, 0}}),
        exact_vector(probe::normalize_call, {{-2e250, 0, 0}}, {-1, 0, 0}, 2 * kUnitRoundoff),
        // Subnormal vectors are finite and nonzero: 1 / |v| overflows, v / |v| does not.
        exact_vector(probe::normalize_call, {{5e-324, 0, 0}}, {1, 0, 0}, 2 * kUnitRoundoff),
        exact_vector(probe::normalize_call, {{-3e-320, 4e-320, 1e-321}},
                     wide_unit({-3e-320, 4e-320, 1e-321}), 2 * kUnitRoundoff),
        exact_vector(probe::reflect_call, {{3, -4, 5}, {0, 0, 1}}, {3, -4, -5}),
        throws_domain_error(probe::perpendicular_to_call, {{1, 2, 3}, {0, 0, 0}}),
        // A tiny or huge `onto` is not zero: onto . onto underflows to 0 or overflows to inf, its
        // unit vector does neither.
        exact_vector(probe::project_onto_call, {{2, 3, 4}, {0, 1e-200, 0}}, {0, 3, 0},
                     2 * kUnitRoundoff),
        exact_vector(probe::project_onto_call, {{2, 3, 4}, {0, -1e200, 0}}, {0, 3, 0},
                     2 * kUnitRoundoff),
        exact_vector(probe::perpendicular_to_call, {{2, 3, 4}, {0, 0, 3e-190}}, {2, 3, 0},
                     8 * kUnitRoundoff),
        throws_domain_error(probe::orthonormal_frame_call, {{0, 0, 0}, {0, 1, 0}}),
        throws_domain_error(probe::orthonormal_frame_call, {{0, 0, 1}, {0, 0, 0}}),
        throws_domain_error(probe::orthonormal_frame_call, {{std::nan(""), 0, 1}, {0, 1, 0}}),
        throws_domain_error(probe::orthonormal_frame_call, {{0, 0, 1}, {1, std::nan(""), 0}}),
        throws_domain_error(probe::orthonormal_frame_call, {{0, -inf, 0}, {1, 0, 0}}),
        throws_domain_error(probe::orthonormal_frame_call, {{0, 0, 1}, {0, inf, 0}}),
        throws_domain_error(probe::orthonormal_frame_call, {{1, 1, 0}, {-2, -2, 0}}),
        // Parallel, but w = a / |a| is rounded, so b x w is a few 1e-16, not zero
        throws_domain_error(probe::orthonormal_frame_call, {{1, 2, 3}, {2, 4, 6}}),
        throws_domain_error(probe::orthonormal_frame_call, {{0.1, 0.2, 0.3}, {-3, -6, -9}}),
        frame_case({0, 0, 1e-150}, {0, 1e150, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}),
        // "Parallel" is relative to |b|: a short b at right angles to a is no more parallel than
        // a long one, and a long b whose sine with a is 1e-10 is parallel though |b x w| is 1e-4.
        frame_case({0, 0, 1}, {0, 1e-10, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}),
        frame_case({1e250, 0, 0}, {0, 0, 1e-250}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}),
        frame_case({0, 0, 1}, {1e300, 1e300, 0}, {r2, -r2, 0}, {r2, r2, 0}, {0, 0, 1}),
        throws_domain_error(probe::orthonormal_frame_call, {{0, 0, 1}, {1e-4, 0, 1e6}}),
        throws_domain_error(probe::orthonormal_frame_call, {{1, 2, 3}, {2e100, 4e100, 6e100}}),
        throws_domain_error(probe::orthonormal_frame_call, {{0, 0, 1}, {1e-210, 0, 1e-200}}),
    };
}

// Random vectors whose components span 1e-100 to 1e100 in magnitude, either sign.
Vec3 random_vector(PortableRandom& random) {
    Vec3 v;
    for (int k = 0; k < 3; ++k) {
        const double mantissa = random.uniform(1.0, 10.0);
        const double exponent = static_cast<double>(random.integer(-100, 100));
        v[k] = mantissa * std::pow(10.0, exponent) * (random.integer(0, 1) ? -1.0 : 1.0);
    }
    return v;
}

// Each kind of random case draws from its own seed, case k from PortableRandom(seed, k), so that
// one case is rebuilt without the others.
constexpr std::uint64_t kProductSeed = 1701;
constexpr std::uint64_t kLengthSeed = 1702;
constexpr std::uint64_t kFrameSeed = 1703;

// dot and cross against long double, each within a few roundings of the sizes of its terms:
// cancellation can take every digit, so the bound is relative to sum |a_i b_i|, not to the answer.
void add_product_cases(std::vector<PublicCase>& cases, std::uint64_t seed, int count) {
    for (int k = 0; k < count; ++k) {
        PortableRandom random(seed, k);
        // Components within 1e±50 of each other, so that products stay in range.
        const Vec3 a = random_vector(random) * 1e-50;
        const Vec3 b = random_vector(random) * 1e-50;
        const Wide exact = Wide(a.x) * b.x + Wide(a.y) * b.y + Wide(a.z) * b.z;
        const Wide size =
            std::abs(Wide(a.x) * b.x) + std::abs(Wide(a.y) * b.y) + std::abs(Wide(a.z) * b.z);
        cases.push_back(exact_number(probe::dot_call, {a, b}, static_cast<double>(exact),
                                     static_cast<double>(4 * kUnitRoundoff * size)));
        const Vec3 c{static_cast<double>(Wide(a.y) * b.z - Wide(a.z) * b.y),
                     static_cast<double>(Wide(a.z) * b.x - Wide(a.x) * b.z),
                     static_cast<double>(Wide(a.x) * b.y - Wide(a.y) * b.x)};
        const double cross_size = static_cast<double>(
            4 * kUnitRoundoff * (std::abs(Wide(a.x)) + std::abs(Wide(a.y)) + std::abs(Wide(a.z))) *
            (std::abs(Wide(b.x)) + std::abs(Wide(b.y)) + std::abs(Wide(b.z))));
        cases.push_back(exact_vector(probe::cross_call, {a, b}, c, cross_size));
    }
}

// length and normalize at every magnitude, squares far beyond a double's range: they must not
// overflow or underflow.
void add_length_cases(std::vector<PublicCase>& cases, std::uint64_t seed, int count) {
    for (int k = 0; k < count; ++k) {
        PortableRandom random(seed, k);
        const Vec3 v = random_vector(random) * (k % 2 ? 1e150 : 1e-150);
        const Wide exact = std::sqrt(Wide(v.x) * v.x + Wide(v.y) * v.y + Wide(v.z) * v.z);
        cases.push_back(exact_number(probe::length_call, {v}, static_cast<double>(exact),
                                     static_cast<double>(3 * kUnitRoundoff * exact)));
        cases.push_back(exact_vector(probe::normalize_call, {v}, wide_unit(v), 4 * kUnitRoundoff));
    }
}

// A direction at `sine` from the unit vector w (a sine below 1 leaves the cosine's sign random).
WideVec tilted(PortableRandom& random, const WideVec& w, Wide sine) {
    WideVec side;
    do {
        side = widen(random.unit_vector());
        side -= glm::dot(side, w) * w;
    } while (glm::length(side) < Wide(0.1));
    side /= glm::length(side);
    const Wide cosine = std::sqrt(1 - sine * sine) * (random.integer(0, 1) ? -1 : 1);
    return cosine * w + sine * side;
}

// orthonormal_frame on a and b of unrelated magnitudes (1e-100 to 1e100 each), against the frame
// worked out in long double. A third are well apart (sine 0.01 to 1); a third nearly parallel
// but a hundredfold above kParallelSine, a frame; a third a hundredfold below it, an error. The
// frame inherits w's rounding, a few ulps of |b|, over |b x w|: its tolerance is 8 ulps / sine.
void add_frame_cases(std::vector<PublicCase>& cases, std::uint64_t seed, int count) {
    for (int k = 0; k < count; ++k) {
        PortableRandom random(seed, k);
        const Vec3 direction = random.unit_vector();
        const Vec3 a = direction * random.decade(-100, 100);
        const WideVec w_wide = widen(direction);
        const Wide sine = k % 3 == 0   ? Wide(random.decade(-2, 0))
                          : k % 3 == 1 ? Wide(kParallelSine) * Wide(random.decade(2, 4))
                                       : Wide(kParallelSine) * Wide(random.decade(-4, -2));
        // One draw per statement: the order of two draws in one expression is the compiler's.
        const WideVec b_direction = tilted(random, w_wide, sine);
        const WideVec b_wide = b_direction * Wide(random.decade(-100, 100));
        const Vec3 b = narrow(b_wide);
        if (k % 3 == 2) {
            cases.push_back(throws_domain_error(probe::orthonormal_frame_call, {a, b}));
            continue;
        }
        // The expectation from the rounded inputs, as the student's code sees them.
        const WideVec w = widen(a) / glm::length(widen(a));
        const WideVec b_cross_w = glm::cross(widen(b), w);
        const Wide actual_sine = glm::length(b_cross_w) / glm::length(widen(b));
        const WideVec u = b_cross_w / glm::length(b_cross_w);
        cases.push_back(frame_case(a, b, narrow(u), narrow(glm::cross(w, u)), narrow(w),
                                   static_cast<double>(8 * kUnitRoundoff / actual_sine)));
    }
}

// The generated cases: `count` of each kind, drawn from the kinds' seeds plus `offset`.
std::vector<PublicCase> generated_cases(std::uint64_t offset, int count) {
    std::vector<PublicCase> cases;
    add_product_cases(cases, kProductSeed + offset, count);
    add_length_cases(cases, kLengthSeed + offset, count);
    add_frame_cases(cases, kFrameSeed + offset, 3 * count / 2);
    return cases;
}

std::vector<ProbeCase> oracle_cases() {
    return data_judged_cases(generated_cases(0, 200));
}

}  // namespace

PublicCheck stage1_public_check() {
    return {"stage1.unit", 1, "unit", kPublicName, public_cases()};
}

PublicCheck stage1_sample_check() {
    return sample_check(1,
                        "dot, cross, length, normalize and orthonormal_frame against long double",
                        generated_cases(kSampleSeedOffset, 10));
}

std::vector<CheckDefinition> stage1_checks() {
    return stage_case_checks(
        {1, kPublicName, [] { return data_judged_cases(public_cases()); },
         "vector functions on the contract's edge cases",
         [] { return data_judged_cases(hidden_cases()); },
         "dot, cross, length, normalize and orthonormal_frame against long double on "
         "random vectors of every magnitude",
         oracle_cases});
}

}  // namespace raystep::grade
