// Stage 7 checks: the mirror ray and the recursion. radiance is asked over a scripted scene (the
// probe's shade returns the script's hits in turn, then misses), so the grader knows every ray
// the recursion should ask about, in order, and the colour it should add up: hand-worked chains
// (public and hidden) and random ones, the sums and the reflections computed in long double
// (grading/7_recursion/recursion_oracle.h). Every case is judged by a data judge
// (grading/7_recursion/recursion_judges.h): the public ones go into the student release as data,
// and the others are judged by the same code.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "base/math/portable_random.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/7_recursion/recursion_calls.h"
#include "grading/7_recursion/recursion_judges.h"
#include "grading/7_recursion/recursion_oracle.h"

namespace raystep::grade {

namespace {

using probe::Json;

const double kInf = std::numeric_limits<double>::infinity();

// The stage's public name, shared by the grader's check and the release's case file.
constexpr const char* kPublicName = "the mirror ray and the recursion over hand-worked chains";

PublicCase reflected_ray_case(const SurfacePoint& p, const RayOffset& offset) {
    return {"reflected_ray(" + point_text(p) + ", " + offset_text(offset) + ")",
            probe::query(probe::reflected_ray_call, {p, offset}),
            mirror_ray_judge(expected_reflection(p, offset)),
            "reflected_ray(" + cpp(p) + ", " + cpp(offset) + ")"};
}

// The header's "unbounded": t_max is infinity, as for a directional light's shadow ray, not a
// large finite number standing in for it.
PublicCase unbounded_case(const SurfacePoint& p, const RayOffset& offset) {
    return {"reflected_ray(" + point_text(p) + ", " + offset_text(offset) + "): unbounded",
            probe::query(probe::reflected_ray_call, {p, offset}), unbounded_ray_judge(),
            "reflected_ray(" + cpp(p) + ", " + cpp(offset) + ").t_max"};
}

// --- radiance over a script

ShadedHit mirror(const SurfacePoint& p, const Color& local, const Color& reflectance) {
    return {p, local, reflectance};
}

std::string script_text(const Script& script) {
    std::string text;
    for (const std::optional<ShadedHit>& hit : script) {
        text += text.empty() ? "" : "; ";
        text += hit ? "hit at " + point_text(hit->point) + ", local " + full_text(hit->local) +
                          ", reflectance " + full_text(hit->reflectance)
                    : "miss";
    }
    return "[" + text + "]";
}

// radiance over the script in a student's test: shade answers from the script in turn, then
// misses, as the probe's does.
std::string radiance_code(const Script& script, const Ray& eye, int bounces,
                          const RayOffset& offset) {
    std::string steps;
    for (const std::optional<ShadedHit>& hit : script) {
        steps +=
            (steps.empty() ? "" : ",\n    ") +
            (hit ? "std::optional<ShadedHit>(" + cpp(*hit) + ")" : std::string("std::nullopt"));
    }
    return "const std::vector<std::optional<ShadedHit>> script = {\n    " + steps +
           "};\n"
           "std::size_t next = 0;\n"
           "std::vector<Ray> asked;  // every ray radiance asks shade about, in order\n"
           "const ShadeFunction shade = [&](const Ray& ray) {\n"
           "    asked.push_back(ray);\n"
           "    return next < script.size() ? script[next++] : std::optional<ShadedHit>();\n"
           "};\n"
           "radiance(shade, " +
           cpp(eye) + ", " + std::to_string(bounces) + ", " + cpp(offset) + ")";
}

PublicCase radiance_case(const Script& script, const Ray& eye, int bounces,
                         const RayOffset& offset) {
    const ExpectedRadiance e = expected_radiance(script, eye, bounces, offset);
    return {"radiance(eye " + ray_text(eye) + ", bounces " + std::to_string(bounces) + ", " +
                offset_text(offset) + ") over the scene " + script_text(script),
            probe::query(probe::radiance_call, {script, eye, bounces, offset}),
            radiance_judge(double_double(e.colour), double_double(e.colour_tolerance), e.rays),
            radiance_code(script, eye, bounces, offset)};
}

// A point on the floor y = 0, seen from the direction `to_eye` (normalized here); the shading
// normal is the geometric one unless given.
SurfacePoint floor_point(const Vec3& position, const Vec3& to_eye,
                         const Vec3& shading_normal = {0, 1, 0}) {
    return {position, {0, 0, 0}, {0, 1, 0}, shading_normal, glm::normalize(to_eye)};
}

const Ray kEye{{0, 1, 0}, {1, -1, 0}, 0.0, kInf};
const RayOffset kErrorBound{OffsetRule::error_bound, 0.0};

std::vector<PublicCase> public_cases() {
    const RayOffset along_ray{OffsetRule::along_ray, 1e-4};
    const RayOffset along_normal{OffsetRule::along_normal, 1e-4};
    const SurfacePoint a = floor_point({1, 0, 0}, {-1, 1, 0});
    const SurfacePoint b = floor_point({2, 0, 3}, {-1, 1, 0});
    const SurfacePoint c = floor_point({-5, 0, 2}, {0, 1, 1});
    const Color red{0.8, 0.1, 0.1};
    const Color grey{0.5, 0.5, 0.5};
    return {
        reflected_ray_case(floor_point({0, 0, 0}, {1, 1, 0}), along_ray),
        reflected_ray_case(floor_point({0, 0, 0}, {0, 1, 0}), along_ray),
        reflected_ray_case(floor_point({3, 0, -2}, {1, 2, 3}), along_normal),
        // An exact point (no rounding error): the error bound d is 0, and only spawn_ray's
        // one-ulp step takes the origin off the floor, to y = 2^-1074.
        reflected_ray_case(floor_point({0, 0, 0}, {1, 1, 0}), kErrorBound),
        unbounded_case(floor_point({3, 0, -2}, {1, 2, 3}), along_normal),
        radiance_case({std::nullopt}, kEye, 5, along_ray),
        radiance_case({mirror(a, red, grey)}, kEye, 0, along_ray),
        radiance_case({mirror(a, red, grey), std::nullopt}, kEye, 1, along_ray),
        radiance_case({mirror(a, red, grey), mirror(b, grey, Color(0.25))}, kEye, 5, along_normal),
        radiance_case({mirror(a, red, grey), mirror(b, grey, Color(0.25))}, kEye, 5, kErrorBound),
        radiance_case({mirror(a, red, {0.9, 0.5, 0.1}), mirror(b, grey, {0.2, 0.3, 0.4}),
                       mirror(c, {0, 0, 1}, grey), mirror(a, Color(1), grey)},
                      kEye, 2, along_ray),
    };
}

// The hidden ones: the contract's edges a student's own tests may not reach.
std::vector<PublicCase> hidden_cases() {
    const RayOffset along_ray{OffsetRule::along_ray, 1e-3};
    const RayOffset along_normal{OffsetRule::along_normal, 1e-3};
    const SurfacePoint a = floor_point({1, 0, 0}, {-1, 1, 0});
    // A bent shading normal: the mirror follows it, not the geometric normal, and the reflected
    // ray leaves below the floor, where along_normal must move the origin.
    const SurfacePoint bent = floor_point({0, 0, 0}, {1, 0.2, 0}, glm::normalize(Vec3{1, 1, 0}));
    // On the plane 0.6 x + 0.8 y = 1e6 far from the origin, off by 1e-12 per coordinate: the
    // error bound d = 1.4e-12 is below half an ulp of 2e6 (2.3e-10), so P + d n rounds back to P
    // and only the one-ulp step puts the origin beyond d.
    const SurfacePoint far_tilted{
        {-1e6, 2e6, -1e6}, Vec3(1e-12), {0.6, 0.8, 0}, {0.6, 0.8, 0}, {0, 0.6, 0.8}};
    Script deep;
    for (int k = 0; k < 12; ++k) {
        deep.push_back(mirror(floor_point({k, 0, 0}, {-1, 1, 0}), Color(0.1 * k), Color(0.9)));
    }
    return {
        reflected_ray_case(bent, along_ray),
        reflected_ray_case(bent, along_normal),
        reflected_ray_case(floor_point({1e6, 0, -1e6}, {0.3, 1, -0.2}), along_normal),
        // The bent mirror ray leaves below the floor: the error bound on the floor's underside.
        reflected_ray_case(bent, kErrorBound),
        reflected_ray_case(far_tilted, kErrorBound),
        unbounded_case(bent, along_ray),
        radiance_case({mirror(far_tilted, Color(0.2), Color(0.5)), mirror(a, Color(0.5), Color(1))},
                      kEye, 4, kErrorBound),
        radiance_case({mirror(a, Color(0.3), Color(0))}, kEye, 3, along_ray),
        radiance_case({mirror(a, Color(0.3), {0, 0.5, 0}), mirror(a, Color(1), Color(0))}, kEye, 3,
                      along_ray),
        // A weak mirror is still a mirror: Ks = (0.004, 0.002, 0.001) is not black, and shows a
        // bright lamp, local (200, 100, 50), as 0.3 + (0.8, 0.2, 0.05).
        radiance_case(
            {mirror(a, Color(0.3), {0.004, 0.002, 0.001}), mirror(a, {200, 100, 50}, Color(0))},
            kEye, 3, along_ray),
        radiance_case({mirror(a, Color(0.3), Color(1))}, kEye, -1, along_ray),
        radiance_case({mirror(bent, Color(0.2), Color(1)), mirror(a, Color(0.5), Color(1))}, kEye,
                      4, along_normal),
        radiance_case(deep, kEye, 10, along_ray),
        radiance_case(
            {mirror(a, Color(0.1), Color(1)), std::nullopt, mirror(a, Color(1), Color(1))}, kEye, 5,
            along_ray),
    };
}

// The generated cases, each drawn from its own generator: the grader's from kOracleSeed, a
// release's sample from kOracleSeed + kSampleSeedOffset.
constexpr std::uint64_t kOracleSeed = 7177;

// A mirror anywhere from the origin to 1e4 away, its rounding error from none to 1e3 ulps of its
// position, seen from the normal's side; its mirror ray at least 0.05 off the geometric tangent
// plane, so that every rule's leaving side is clear.
SurfacePoint random_mirror_point(PortableRandom& random) {
    SurfacePoint p;
    p.position = random.unit_vector() * random.decade(0, 4);
    const double size =
        std::max({std::abs(p.position.x), std::abs(p.position.y), std::abs(p.position.z)});
    const double error = random.unit() < 0.2 ? 0.0 : std::ldexp(size, -52) * random.decade(0, 3);
    p.error = {random.uniform(0, error), random.uniform(0, error), random.uniform(0, error)};
    p.normal = random.unit_vector();
    p.shading_normal = glm::normalize(p.normal + 0.2 * random.unit_vector());
    for (;;) {
        p.to_eye = random.unit_vector();
        if (glm::dot(p.to_eye, p.normal) < 0) p.to_eye = -p.to_eye;
        const Vec3 mirrored =
            2 * glm::dot(p.to_eye, p.shading_normal) * p.shading_normal - p.to_eye;
        if (std::abs(glm::dot(mirrored, p.normal)) >= 0.05 * glm::length(mirrored)) return p;
    }
}

// A random chain of up to six mirrors with random bounces (some fewer than the chain, some more),
// reflectances (some black) and each offset rule in turn.
PublicCase random_radiance_case(PortableRandom& random, int k) {
    Script script;
    const std::int64_t length = random.integer(0, 6);
    for (std::int64_t i = 0; i < length; ++i) {
        const SurfacePoint p = random_mirror_point(random);
        const Color reflectance =
            i % 4 == 3 ? Color(0) : Color(random.unit(), random.unit(), random.unit());
        script.push_back(mirror(p, {random.unit(), random.unit(), random.unit()}, reflectance));
    }
    if (k % 5 == 0) script.push_back(std::nullopt);
    const Ray eye{random.unit_vector() * 10.0, random.unit_vector(), 0.0, kInf};
    const OffsetRule rules[] = {OffsetRule::along_ray, OffsetRule::along_normal,
                                OffsetRule::error_bound};
    const OffsetRule rule = rules[k % 3];
    const RayOffset offset{rule, rule == OffsetRule::error_bound ? 0.0 : random.decade(-6, -2)};
    const int bounces = static_cast<int>(random.integer(0, 6));
    return radiance_case(script, eye, bounces, offset);
}

// `count` radiance cases drawn from `seed`, case k from PortableRandom(seed, k), so that
// `--case k` rebuilds that case alone on any platform.
std::vector<PublicCase> generated_cases(std::uint64_t seed, int count) {
    std::vector<PublicCase> cases;
    for (int k = 0; k < count; ++k) {
        PortableRandom random(seed, k);
        cases.push_back(random_radiance_case(random, k));
    }
    return cases;
}

std::vector<ProbeCase> oracle_cases() {
    return data_judged_cases(generated_cases(kOracleSeed, 300));
}

}  // namespace

PublicCheck stage7_public_check() {
    return {"stage7.unit", 7, "unit", kPublicName, public_cases()};
}

PublicCheck stage7_sample_check() {
    return sample_check(7,
                        "random mirror chains: every ray asked and the colour, against long double",
                        generated_cases(kOracleSeed + kSampleSeedOffset, 15));
}

std::vector<CheckDefinition> stage7_checks() {
    return stage_case_checks(
        {7, kPublicName, [] { return data_judged_cases(public_cases()); },
         "black mirrors, no bounces, bent shading normals and deep chains",
         [] { return data_judged_cases(hidden_cases()); },
         "random mirror chains: every ray asked and the colour, against long double",
         oracle_cases});
}

}  // namespace raystep::grade
