// Stage 9 checks: Snell's law, the Fresnel reflectances, the media a ray is in, the refracted ray
// and the recursion through glass. Snell's direction, both reflectances and the refracted ray
// are decided in long double with the rounding budget of a right formula in double
// (grading/9_refraction/refraction_oracle.h): on hand-worked cases (public), on the contract's hard
// cases (hidden: normal incidence, grazing, at and one ulp either side of the critical angle,
// eta 1 and far from 1, Brewster's angle, normals off the axes) and on seeded random ones. The
// media are exact, on named cases. radiance_with_refraction runs over fake scenes
// (stage9_radiance_cases.h). Three edges of the contract that a bug may break alone are checks of
// their own: leaving a solid's latest entry, the shading normal's cosine, and a cosine that rounds
// above 1. Every case is judged by a data judge, so the public ones go into
// the student release as data and the others are judged by the same code.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/grade/value_judges.h"
#include "base/math/portable_random.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/7_recursion/recursion_judges.h"
#include "grading/9_refraction/refraction_calls.h"
#include "grading/9_refraction/refraction_judges.h"
#include "grading/9_refraction/refraction_oracle.h"
#include "grading/9_refraction/stage9_radiance_cases.h"

namespace raystep::grade {

namespace {

using probe::Json;

constexpr const char* kPublicName =
    "Snell's law, Fresnel, the media and the recursion through glass on hand-worked cases";

const Medium kGlass{1, 1.5};
const Medium kWater{2, 1.33};
const Medium kDiamond{3, 2.4};
// A second glass solid of glass's index: leaving one of two equal-index solids must remove that
// solid, found by its number, not by its index.
const Medium kOtherGlass{4, 1.5};

AllowedAnswers allowed(RefractionAnswer answer) {
    return {answer != RefractionAnswer::none, answer != RefractionAnswer::direction};
}

std::string media_code(const MediumStack& stack) {
    std::string text;
    for (const Medium& m : stack) {
        text += (text.empty() ? "" : ", ") + std::string("Medium{") + std::to_string(m.solid) +
                ", " + cpp(m.index) + "}";
    }
    return "MediumStack{" + text + "}";
}

std::string media_text(const MediumStack& stack) {
    std::string text;
    for (const Medium& m : stack)
        text +=
            (text.empty() ? "" : ", ") + std::to_string(m.solid) + " (" + full_text(m.index) + ")";
    return "[" + text + "]";
}

// --- One call, one case

PublicCase refract_case(const Vec3& incident, const Vec3& normal, double eta) {
    const ExpectedRefraction e = expected_refraction(incident, normal, eta);
    const std::string args = cpp(incident) + ", " + cpp(normal) + ", " + cpp(eta);
    return {
        "refract(" + vectors_text({incident, normal}) + ", eta " + full_text(eta) + ")",
        probe::query(probe::refract_call, {incident, normal, eta}),
        refraction_judge(allowed(e.answer), double_double(e.direction), double_double(e.tolerance)),
        "refract(" + args + ")"};
}

// Snell's law with the incident direction at `degrees` from the normal, in the plane of the
// normal and `along` (both normalized here).
PublicCase refract_at(double degrees, const Vec3& normal, const Vec3& along, double eta) {
    const Vec3 n = glm::normalize(normal);
    const Vec3 t = glm::normalize(along - glm::dot(along, n) * n);
    const double angle = degrees * 3.14159265358979323846 / 180;
    return refract_case(glm::normalize(std::sin(angle) * t - std::cos(angle) * n), n, eta);
}

PublicCase fresnel_case(bool schlick, double cos_incident, double n1, double n2) {
    const ExpectedNumber e = schlick ? expected_fresnel_schlick(cos_incident, n1, n2)
                                     : expected_fresnel_exact(cos_incident, n1, n2);
    const auto& call = schlick ? probe::fresnel_schlick_call : probe::fresnel_exact_call;
    const std::string name = call.name;
    return {name + "(cos " + full_text(cos_incident) + ", n1 " + full_text(n1) + ", n2 " +
                full_text(n2) + ")",
            probe::query(call, {cos_incident, n1, n2}),
            near_wide_number_judge(double_double(e.value), double_double(e.tolerance)),
            name + "(" + cpp(cos_incident) + ", " + cpp(n1) + ", " + cpp(n2) + ")"};
}

PublicCase current_index_case(const MediumStack& inside, double expected) {
    return {"current_index(" + media_text(inside) + ")",
            probe::query(probe::current_index_call, {inside}), near_number_judge(expected, 0.0),
            "current_index(" + media_code(inside) + ")"};
}

PublicCase after_crossing_case(const MediumStack& inside, const Medium& solid, bool entering,
                               const MediumStack& expected) {
    const std::string solid_code =
        "Medium{" + std::to_string(solid.solid) + ", " + cpp(solid.index) + "}";
    return {"after_crossing(" + media_text(inside) + ", solid " + std::to_string(solid.solid) +
                " (" + full_text(solid.index) + "), " + (entering ? "entering" : "leaving") + ")",
            probe::query(probe::after_crossing_call, {inside, solid, entering}),
            media_judge(expected),
            "after_crossing(" + media_code(inside) + ", " + solid_code + ", " +
                (entering ? "true" : "false") + ")"};
}

PublicCase refracted_ray_case(const SurfacePoint& p, double n1, double n2,
                              const RayOffset& offset) {
    const ExpectedRefractedRay e = expected_refracted_ray(p, n1, n2, offset);
    return {"refracted_ray(" + point_text(p) + ", n1 " + full_text(n1) + ", n2 " + full_text(n2) +
                ", " + offset_text(offset) + ")",
            probe::query(probe::refracted_ray_call, {p, n1, n2, offset}),
            refracted_ray_judge(allowed(e.answer), e.ray),
            "refracted_ray(" + cpp(p) + ", " + cpp(n1) + ", " + cpp(n2) + ", " + cpp(offset) + ")"};
}

// The header's "unbounded": t_max is infinity, not a large finite number standing in for it. The
// other cases accept the largest double there, which admits the same hits (recursion_judges.h).
PublicCase unbounded_case(const SurfacePoint& p, double n1, double n2, const RayOffset& offset) {
    PublicCase c = refracted_ray_case(p, n1, n2, offset);
    c.input += ": unbounded";
    c.judge = unbounded_ray_judge();
    c.reproduce += "->t_max";
    return c;
}

// A point on the floor y = 0 seen from `to_eye` (normalized here), the shading normal the
// geometric one unless given.
SurfacePoint floor_point(const Vec3& position, const Vec3& to_eye,
                         const Vec3& shading_normal = {0, 1, 0}) {
    return {position, {0, 0, 0}, {0, 1, 0}, glm::normalize(shading_normal), glm::normalize(to_eye)};
}

const RayOffset kAlongRay{OffsetRule::along_ray, 1e-4};
const RayOffset kAlongNormal{OffsetRule::along_normal, 1e-4};
const RayOffset kErrorBound{OffsetRule::error_bound, 0.0};
const Vec3 kUp{0, 1, 0};
const Vec3 kX{1, 0, 0};

std::vector<PublicCase> public_cases() {
    const double into_glass = 1 / 1.5;
    std::vector<PublicCase> cases = {
        refract_case({0, -1, 0}, kUp, into_glass),
        refract_at(45, kUp, kX, into_glass),
        refract_at(60, kUp, kX, 1.5),
        refract_at(30, kUp, kX, 1.0),
        fresnel_case(false, 1.0, 1.0, 1.5),
        fresnel_case(false, 1 / std::sqrt(3.25), 1.0, 1.5),  // Brewster's angle: r_p = 0
        fresnel_case(false, 0.5, 1.5, 1.0),
        fresnel_case(true, std::sqrt(0.5), 1.0, 1.5),
        fresnel_case(true, std::sqrt(3.0) / 2, 1.5, 1.0),
        current_index_case({}, 1.0),
        current_index_case({kGlass, kWater}, 1.33),
        after_crossing_case({}, kGlass, true, {kGlass}),
        after_crossing_case({kGlass, kWater}, kWater, false, {kGlass}),
        refracted_ray_case(floor_point({1, 0, 2}, {-1, 1, 0}), 1.0, 1.5, kAlongRay),
        refracted_ray_case(floor_point({1, 0, 2}, {-2, 1, 0}), 1.5, 1.0, kAlongRay),
    };
    for (PublicCase& c : stage9_public_radiance_cases())
        cases.push_back(std::move(c));
    return cases;
}

std::vector<PublicCase> hidden_cases() {
    const double into_glass = 1 / 1.5;
    // The critical angle leaving glass: sin = 1 / 1.5, and the incident direction at it with
    // its tangential component one ulp either side.
    const double sin_c = 1 / 1.5;
    const Vec3 critical{sin_c, -std::sqrt(1 - sin_c * sin_c), 0};
    const Vec3 tilted = glm::normalize(Vec3{1, 2, 3});
    std::vector<PublicCase> cases = {
        // Snell: head-on both ways, grazing, eta 1, eta far from 1
        refract_case({0, -1, 0}, kUp, 1.5),
        refract_case(kX, kUp, into_glass),
        refract_case(kX, kUp, 1.5),
        refract_case(kX, kUp, 1.0),
        refract_at(89.999, kUp, kX, into_glass),
        refract_at(17, kUp, {0, 0, 1}, 1 / 2.4),
        refract_at(17, kUp, kX, 2.4),
        refract_at(3, kUp, kX, 10.0),
        refract_at(80, kUp, kX, 0.1),
        // at the critical angle and one ulp either side: either answer, never a NaN
        refract_case(critical, kUp, 1.5),
        refract_case({std::nextafter(critical.x, 1.0), critical.y, 0}, kUp, 1.5),
        refract_case({std::nextafter(critical.x, 0.0), critical.y, 0}, kUp, 1.5),
        refract_at(41.8103148957786, tilted, {1, 0, 0}, 1.5),
        refract_at(41.82, tilted, {1, 0, 0}, 1.5),
        refract_at(41.80, tilted, {1, 0, 0}, 1.5),
        // normals off the axes
        refract_at(30, tilted, {0, 1, 0}, into_glass),
        refract_at(70, glm::normalize(Vec3{-3, 0.5, 1}), {1, 1, 1}, 1.33),
        refract_at(20, glm::normalize(Vec3{-3, 0.5, 1}), {1, 1, 1}, 1.33 / 1.5),
        // Fresnel, exact: both sides, beyond the critical angle, Brewster's, head-on, grazing
        fresnel_case(false, 0.8, 1.0, 1.5),
        fresnel_case(false, 0.8, 1.5, 1.0),
        fresnel_case(false, 1.0, 1.5, 1.0),
        fresnel_case(false, 0.0, 1.0, 1.5),
        fresnel_case(false, 0.3, 1.5, 1.0),
        fresnel_case(false, 1.5 / std::sqrt(3.25), 1.5, 1.0),  // Brewster's angle from inside
        fresnel_case(false, std::sqrt(1 - sin_c * sin_c), 1.5, 1.0),
        fresnel_case(false, 0.6, 1.33, 1.33),
        fresnel_case(false, 0.05, 1.0, 2.4),
        fresnel_case(false, 0.999, 2.4, 1.0),
        // Schlick: the less dense side's cosine, 1 beyond the critical angle
        fresnel_case(true, 1.0, 1.0, 1.5),
        fresnel_case(true, 1.0, 1.5, 1.0),
        fresnel_case(true, 0.0, 1.0, 1.5),
        fresnel_case(true, 0.8, 1.5, 1.0),
        fresnel_case(true, 0.9, 1.5, 1.33),
        fresnel_case(true, 0.3, 1.5, 1.0),
        fresnel_case(true, 0.95, 2.4, 1.0),
        // The media: nested, overlapping, never entered, entered twice
        current_index_case({kGlass}, 1.5),
        current_index_case({kWater, kGlass}, 1.5),
        after_crossing_case({kGlass}, kWater, true, {kGlass, kWater}),
        after_crossing_case({kGlass, kWater}, kGlass, false, {kWater}),
        after_crossing_case({kGlass, kWater, kDiamond}, kWater, false, {kGlass, kDiamond}),
        after_crossing_case({kGlass}, kWater, false, {kGlass}),
        after_crossing_case({}, kGlass, false, {}),
        after_crossing_case({kGlass}, kGlass, true, {kGlass, kGlass}),
        after_crossing_case({kGlass, kGlass}, kGlass, false, {kGlass}),
        after_crossing_case({kWater, kGlass, kGlass}, kGlass, false, {kWater, kGlass}),
        after_crossing_case({kGlass, kOtherGlass}, kGlass, false, {kOtherGlass}),
        after_crossing_case({kOtherGlass, kWater, kGlass}, kOtherGlass, false, {kWater, kGlass}),
        // The refracted ray: each offset rule, far from the origin, total internal reflection
        refracted_ray_case(floor_point({1, 0, 2}, {-1, 1, 0}), 1.0, 1.5, kAlongNormal),
        refracted_ray_case(floor_point({1, 0, 2}, {-1, 1, 0}), 1.0, 1.5, kErrorBound),
        refracted_ray_case(floor_point({1e6, 0, -1e6}, {0.3, 1, -0.2}), 2.4, 1.0,
                           {OffsetRule::along_normal, 1e-3}),
        refracted_ray_case(floor_point({1e6, 0, -1e6}, {0.3, 1, -0.2}), 1.0, 2.4, kErrorBound),
        refracted_ray_case(floor_point({3, 0, 3}, {-3, 1, 0}), 1.5, 1.0, kAlongNormal),
        refracted_ray_case(floor_point({3, 0, 3}, {1, 1, 1}), 1.0, 1.0, kAlongRay),
        unbounded_case(floor_point({1, 0, 2}, {-1, 1, 0}), 1.0, 1.5, kAlongNormal),
    };
    for (PublicCase& c : stage9_hidden_radiance_cases())
        cases.push_back(std::move(c));
    return cases;
}

// --- The contract's edges that a check of their own holds (the rubric takes all its points for
// one wrong case: each is one promise, kept or broken)

// Leaving a solid the stack holds twice, another solid entered between: its latest entry goes.
std::vector<PublicCase> latest_entry_cases() {
    std::vector<PublicCase> cases = {
        after_crossing_case({kGlass, kWater, kGlass}, kGlass, false, {kGlass, kWater}),
        after_crossing_case({kGlass, kWater, kGlass, kDiamond}, kGlass, false,
                            {kGlass, kWater, kDiamond}),
        after_crossing_case({kWater, kGlass, kDiamond, kGlass, kWater}, kGlass, false,
                            {kWater, kGlass, kDiamond, kWater}),
    };
    for (PublicCase& c : stage9_latest_entry_radiance_cases())
        cases.push_back(std::move(c));
    return cases;
}

// A shading normal bent from the geometric one: the refracted ray bends about it, and F takes
// its cosine from it.
std::vector<PublicCase> shading_normal_cases() {
    std::vector<PublicCase> cases = {
        refracted_ray_case(floor_point({0, 0, 0}, {1, 2, 0.5}, {0.2, 1, 0}), 1.0, 1.33,
                           kAlongNormal),
        refracted_ray_case(floor_point({0, 0, 0}, {1, 2, 0.5}, {0.2, 1, 0}), 1.5, 1.0, kErrorBound),
    };
    for (PublicCase& c : stage9_shading_normal_radiance_cases())
        cases.push_back(std::move(c));
    return cases;
}

// A cosine that rounds above 1, as V . N of two equal unit vectors may: no NaN from a sine taken
// as sqrt(1 - cos^2), in either Fresnel formula, in Snell's law, or in the recursion.
std::vector<PublicCase> cosine_above_one_cases() {
    const double above_one = std::nextafter(1.0, 2.0);
    const Vec3 v = unit_vector_squaring_above_one();
    std::vector<PublicCase> cases = {
        fresnel_case(false, above_one, 1.0, 1.5),
        fresnel_case(false, above_one, 1.5, 1.0),
        fresnel_case(true, above_one, 1.0, 1.5),
        fresnel_case(true, above_one, 1.5, 1.0),
        refract_case(-v, v, 1 / 1.5),
        refract_case(-v, v, 1.5),
    };
    for (PublicCase& c : stage9_cosine_above_one_radiance_cases())
        cases.push_back(std::move(c));
    return cases;
}

// --- Generated cases

constexpr std::uint64_t kOracleSeed = 9199;

// An index ratio: near 1, far from it, or between common media.
double random_eta(PortableRandom& random, int k) {
    switch (k % 4) {
        case 0:
            return random.uniform(0.6, 1.7);
        case 1:
            return random.decade(-1, 1);
        case 2: {
            const double indices[] = {1.0, 1.33, 1.5, 2.4};
            return indices[random.integer(0, 3)] / indices[random.integer(0, 3)];
        }
        default:
            return 1 / random.uniform(1.0, 2.5);
    }
}

// A unit normal anywhere, and an incident direction on its side: uniform over the hemisphere,
// or (every fifth case, for eta above 1) within 1e-12 relative of the critical angle, either
// side, where the refracted direction turns fastest.
PublicCase random_refract_case(PortableRandom& random, int k) {
    const Vec3 normal = random.unit_vector();
    const double eta = random_eta(random, k);
    if (k % 5 == 4 && eta > 1) {
        const double sin1 = std::min(1.0, (1 / eta) * (1 + random.uniform(-1e-12, 1e-12)));
        Vec3 along = random.unit_vector();
        along = glm::normalize(along - glm::dot(along, normal) * normal);
        const Vec3 incident =
            glm::normalize(sin1 * along - std::sqrt(std::max(0.0, 1 - sin1 * sin1)) * normal);
        return refract_case(incident, normal, eta);
    }
    Vec3 incident = random.unit_vector();
    if (glm::dot(incident, normal) > 0) incident = -incident;
    return refract_case(incident, normal, eta);
}

PublicCase random_fresnel_case(PortableRandom& random, int k) {
    const double indices[] = {1.0, 1.33, 1.5, 2.4};
    const double n1 = k % 3 == 0 ? random.uniform(1.0, 3.0) : indices[random.integer(0, 3)];
    const double n2 = k % 3 == 1 ? random.uniform(1.0, 3.0) : indices[random.integer(0, 3)];
    return fresnel_case(k % 2 == 1, random.unit(), n1, n2);
}

// A surface point anywhere from the origin to 1e4 away, its rounding error from none to 1e3
// ulps, a shading normal bent from the geometric one, seen from the normal's side; redrawn
// until the refracted ray, if any, leaves at least 0.05 off the geometric tangent plane and
// sin^2(theta2) is at least 1e-3 from 1, where every rule's leaving side and the total internal
// reflection are clear.
PublicCase random_refracted_ray_case(PortableRandom& random, int k) {
    const double indices[] = {1.0, 1.33, 1.5, 2.4};
    const double n1 = indices[random.integer(0, 3)];
    const double n2 = indices[random.integer(0, 3)];
    SurfacePoint p;
    p.position = random.unit_vector() * random.decade(0, 4);
    const double size =
        std::max({std::abs(p.position.x), std::abs(p.position.y), std::abs(p.position.z)});
    const double error = random.unit() < 0.2 ? 0.0 : std::ldexp(size, -52) * random.decade(0, 3);
    p.error = {random.uniform(0, error), random.uniform(0, error), random.uniform(0, error)};
    p.normal = random.unit_vector();
    p.shading_normal = glm::normalize(p.normal + 0.2 * random.unit_vector());
    const double eta = n1 / n2;
    for (;;) {
        p.to_eye = random.unit_vector();
        if (glm::dot(p.to_eye, p.normal) < 0) p.to_eye = -p.to_eye;
        const double cos1 = glm::dot(p.to_eye, p.shading_normal);
        if (cos1 < 0.05) continue;
        const double q = 1 - eta * eta * (1 - cos1 * cos1);
        if (std::abs(q) < 1e-3) continue;
        const ExpectedRefraction r = expected_refraction(-p.to_eye, p.shading_normal, eta);
        if (r.answer == RefractionAnswer::none) break;
        if (std::abs(glm::dot(narrow(r.direction), p.normal)) >= 0.05) break;
    }
    const OffsetRule rules[] = {OffsetRule::along_ray, OffsetRule::along_normal,
                                OffsetRule::error_bound};
    const OffsetRule rule = rules[k % 3];
    const RayOffset offset{rule, rule == OffsetRule::error_bound ? 0.0 : random.decade(-6, -2)};
    return refracted_ray_case(p, n1, n2, offset);
}

// Each family's cases drawn from its own generators: case k of a family from
// PortableRandom(seed + family, k), so that `--case` rebuilds a case alone on any platform.
std::vector<PublicCase> generated_cases(std::uint64_t seed, int count) {
    std::vector<PublicCase> cases;
    const auto family = [&](std::uint64_t offset, int n, auto make) {
        for (int k = 0; k < n; ++k) {
            PortableRandom random(seed + offset, k);
            cases.push_back(make(random, k));
        }
    };
    family(0, 2 * count, random_refract_case);
    family(1, count, random_fresnel_case);
    family(2, count, random_refracted_ray_case);
    family(3, count, stage9_random_radiance_case);
    return cases;
}

std::vector<ProbeCase> oracle_cases() {
    return data_judged_cases(generated_cases(kOracleSeed, 100));
}

}  // namespace

PublicCheck stage9_public_check() {
    return {"stage9.unit", 9, "unit", kPublicName, public_cases()};
}

PublicCheck stage9_sample_check() {
    return sample_check(9,
                        "random refractions, reflectances, refracted rays and trees of glass, "
                        "against long double",
                        generated_cases(kOracleSeed + kSampleSeedOffset, 4));
}

std::vector<CheckDefinition> stage9_checks() {
    std::vector<CheckDefinition> checks = stage_case_checks(
        {9, kPublicName, [] { return data_judged_cases(public_cases()); },
         "the critical angle, grazing and head-on light, Brewster's angle, nested and "
         "overlapping media, F once, black weights and bounces cut",
         [] { return data_judged_cases(hidden_cases()); },
         "random refractions, reflectances, refracted rays and trees of glass, against long "
         "double",
         oracle_cases});
    checks.push_back(case_check("stage9.hidden.latest_entry", 9, "unit",
                                "leaving a solid entered twice, another between, removes its "
                                "latest entry",
                                [] { return data_judged_cases(latest_entry_cases()); }));
    checks.push_back(case_check("stage9.hidden.shading_normal", 9, "unit",
                                "Fresnel's cosine and the refracted ray from a bent shading normal",
                                [] { return data_judged_cases(shading_normal_cases()); }));
    checks.push_back(case_check("stage9.hidden.cosine_above_one", 9, "unit",
                                "a cosine that rounds above 1 gives no NaN",
                                [] { return data_judged_cases(cosine_above_one_cases()); }));
    return checks;
}

}  // namespace raystep::grade
