// Stage 6 checks: lights, the local model and rays that leave a surface, on hand-worked values
// (public and hidden), and on random inputs against the same sums computed in long double
// (grading/6_shading/shading_oracle.h); for the error-bound rule, what the contract promises (an
// origin strictly beyond the error box along the leaving side's normal, within a few ulps of it),
// decided in long double (grader/oracle/error_bound_origin.h). Every case is judged by a data
// judge (grading/6_shading/shading_judges.h, app/grade/value_judges.h): the public ones go into the
// student release as data, and the others are judged by the same code.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>

#include <glm/geometric.hpp>

#include "app/grade/value_judges.h"
#include "base/math/portable_random.h"
#include "base/math/unit_roundoff.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/oracle/error_bound_origin.h"
#include "grading/6_shading/shading_calls.h"
#include "grading/6_shading/shading_judges.h"
#include "grading/6_shading/shading_oracle.h"

namespace raystep::grade {

namespace {

using probe::Json;

const double kInf = std::numeric_limits<double>::infinity();

// The stage's public name, shared by the grader's check and the release's case file.
constexpr const char* kPublicName =
    "lights, Blinn-Phong, the local model and ray offsets on hand-worked values";

// A colour within its tolerance per channel.
Json near_channels(const WideColor& expected) {
    return near_wide_vec3_judge(double_double(expected.value), double_double(expected.tolerance));
}

Material material(const Color& ambient, const Color& diffuse, const Color& specular,
                  const Color& emission, double shininess) {
    Material m;
    m.ambient = ambient;
    m.diffuse = diffuse;
    m.specular = specular;
    m.emission = emission;
    m.shininess = shininess;
    return m;
}

// A lit point for shading: the shading normal is the geometric one unless given.
SurfacePoint lit_point(const Vec3& normal, const Vec3& to_eye) {
    return {{0, 0, 0}, {0, 0, 0}, normal, normal, to_eye};
}

std::string material_text(const Material& m) {
    return "ambient " + full_text(m.ambient) + ", diffuse " + full_text(m.diffuse) + ", specular " +
           full_text(m.specular) + ", emission " + full_text(m.emission) + ", shininess " +
           full_text(m.shininess);
}

// --- Lights

PublicCase attenuation_case(const Attenuation& a, double distance) {
    // Every term is non-negative: the sum of three roundings or so of each.
    const Wide expected = wide_attenuation(a, distance);
    const double tolerance = static_cast<double>(6 * kUnitRoundoff * expected);
    return {"attenuation(" + full_text(Vec3(a.constant, a.linear, a.quadratic)) + ", " +
                full_text(distance) + ")",
            probe::query(probe::attenuation_call, {a, distance}),
            near_number_judge(static_cast<double>(expected), tolerance),
            "attenuation(" + cpp(a) + ", " + cpp(distance) + ")"};
}

// The light sample's direction, distance and intensity, each within its tolerance, and an
// exact distance where one is asked (infinity for a directional light).
Json sample_judge(const WideLightSample& expected) {
    const Wide distance = expected.distance;
    const Wide distance_tolerance = std::isinf(distance) ? 0 : 8 * kUnitRoundoff * distance;
    return light_sample_judge(double_double(expected.direction), 8 * kUnitRoundoff,
                              double_double(distance), double_double(distance_tolerance),
                              double_double(expected.intensity),
                              double_double(expected.intensity_tolerance));
}

PublicCase point_light_case(const PointLight& light, const Vec3& point) {
    const WideLightSample expected = wide_point_light(light, point);
    const Attenuation& a = light.attenuation;
    return {"sample_light(point light at " + full_text(light.position) + ", colour " +
                full_text(light.color) + ", attenuation " +
                full_text(Vec3(a.constant, a.linear, a.quadratic)) + ") from " + full_text(point),
            probe::query(probe::sample_point_light_call, {light, point}), sample_judge(expected),
            "sample_light(" + cpp(light) + ", " + cpp(point) + ")"};
}

PublicCase at_the_light_case(const PointLight& light) {
    return {"sample_light(point light at " + full_text(light.position) + ") from the light itself",
            probe::query(probe::sample_point_light_call, {light, light.position}),
            threw_judge("domain_error"),
            "sample_light(" + cpp(light) + ", " + cpp(light.position) + ")"};
}

// Never attenuated: the intensity is the colour itself, the distance infinite.
PublicCase directional_light_case(const DirectionalLight& light) {
    const WideLightSample expected = wide_directional_light(light);
    return {"sample_light(directional light towards " + full_text(light.direction) + ", colour " +
                full_text(light.color) + ")",
            probe::query(probe::sample_directional_light_call, {light}), sample_judge(expected),
            "sample_light(" + cpp(light) + ")"};
}

// --- Blinn-Phong

PublicCase blinn_phong_case(const Material& m, const SurfacePoint& p, const LightSample& l) {
    const WideColor expected = wide_blinn_phong(m, p, l);
    return {"blinn_phong(" + material_text(m) + "; " + point_text(p) + "; " + light_sample_text(l) +
                ")",
            probe::query(probe::blinn_phong_call, {m, p, l}), near_channels(expected),
            "blinn_phong(" + cpp(m) + ", " + cpp(p) + ", " + cpp(l) + ")"};
}

PublicCase local_shading_case(const Material& m, const SurfacePoint& p,
                              const std::vector<LightSample>& lights) {
    const WideColor expected = wide_local_shading(m, p, lights);
    std::string text;
    std::string code;
    for (const LightSample& l : lights) {
        text += "; " + light_sample_text(l);
        code += (code.empty() ? "" : ", ") + cpp(l);
    }
    return {"local_shading(" + material_text(m) + "; " + point_text(p) + text + ")",
            probe::query(probe::local_shading_call, {m, p, lights}), near_channels(expected),
            "local_shading(" + cpp(m) + ", " + cpp(p) + ", {" + code + "})"};
}

// --- Rays that leave a surface

// The ray spawn_ray must give, judged by its rule:
// - along_ray: origin the point itself, t over [epsilon, distance];
// - along_normal: origin P + epsilon n, n on the leaving side, within the rounding of that sum;
// - error_bound: the origin in the region error_bound_origin.h describes, t over [0, distance].
// Every rule keeps the direction (a few ulps allowed for renormalizing a unit vector) and ends at
// exactly `distance`.
Json spawned_judge(const SurfacePoint& p, const Vec3& direction, double distance,
                   const RayOffset& offset) {
    const LeavingDirection end{direction, 8 * kUnitRoundoff, distance};
    switch (offset.rule) {
        case OffsetRule::along_ray:
            return along_ray_judge(p.position, offset.epsilon, end);
        case OffsetRule::along_normal: {
            const WideVec n = leaving_normal(p, direction);
            const WideVec origin = widen(p.position) + Wide(offset.epsilon) * n;
            const WideVec tolerance =
                Wide(4 * kUnitRoundoff) *
                (glm::abs(widen(p.position)) + glm::abs(Wide(offset.epsilon) * n));
            return along_normal_judge(double_double(origin), double_double(tolerance), end);
        }
        case OffsetRule::error_bound:
            break;
    }
    return error_bound_judge(error_bound_origin(p, direction), end);
}

PublicCase spawn_case(const SurfacePoint& p, const Vec3& direction, double distance,
                      const RayOffset& offset) {
    return {"spawn_ray(" + point_text(p) + "; direction " + full_text(direction) + ", distance " +
                full_text(distance) + ", " + offset_text(offset) + ")",
            probe::query(probe::spawn_ray_call, {p, direction, distance, offset}),
            spawned_judge(p, direction, distance, offset),
            "spawn_ray(" + cpp(p) + ", " + cpp(direction) + ", " + cpp(distance) + ", " +
                cpp(offset) + ")"};
}

PublicCase shadow_case(const SurfacePoint& p, const LightSample& l, const RayOffset& offset) {
    return {"shadow_ray(" + point_text(p) + "; " + light_sample_text(l) + ", " +
                offset_text(offset) + ")",
            probe::query(probe::shadow_ray_call, {p, l, offset}),
            spawned_judge(p, l.direction, l.distance, offset),
            "shadow_ray(" + cpp(p) + ", " + cpp(l) + ", " + cpp(offset) + ")"};
}

const RayOffset kErrorBound{OffsetRule::error_bound, 0.0};

RayOffset along_ray(double epsilon) {
    return {OffsetRule::along_ray, epsilon};
}

RayOffset along_normal(double epsilon) {
    return {OffsetRule::along_normal, epsilon};
}

std::vector<PublicCase> public_cases() {
    const Vec3 up{0, 1, 0};
    const Material no_light = material(Color(0.0), Color(0.0), Color(0.0), Color(0.0), 1.0);
    // On the plane x = -1, facing -x, whose x may be off by 2e-15 (9 ulps of 1).
    const SurfacePoint wall{{-1, 4, 2}, {2e-15, 0, 0}, {-1, 0, 0}, {-1, 0, 0}, {-0.6, 0, 0.8}};
    SurfacePoint coarse_wall = wall;
    coarse_wall.error = {2e-12, 0, 0};
    const Vec3 out{-0.8, 0, 0.6};   // n . out = 0.8: leaves on the normal's side
    const Vec3 back{0.8, 0, 0.6};   // n . back = -0.8: through the wall
    const Vec3 along{0, 0.6, 0.8};  // n . along = 0: in the tangent plane
    const Material mixed = material({0.1, 0.1, 0.1}, Color(0.5), Color(0.0), {0, 0.25, 0}, 1.0);
    return {
        // 1 + 0.5 * 3 + 0.25 * 9 = 1 + 1.5 + 2.25.
        attenuation_case({1, 0.5, 0.25}, 3),
        attenuation_case({2, 0, 0}, 123.456),
        // From (-1, 1, -1) to (2, 5, -1): (3, 4, 0), 5 away, L = (0.6, 0.8, 0);
        // att = 1 + 0.2 * 5 + 0.04 * 25 = 3, so the intensity is (3, 1.5, 0.75) / 3.
        point_light_case({{2, 5, -1}, {3, 1.5, 0.75}, {1, 0.2, 0.04}}, {-1, 1, -1}),
        at_the_light_case({{-2, 0.5, 7}, {1, 1, 1}, {1, 0, 0}}),
        // (0, -6, 8) has length 10: L = (0, -0.6, 0.8), at infinity, the colour unchanged.
        directional_light_case({{0, -6, 8}, {0.3, 0.6, 0.9}}),
        // Lambert: N . L = 0.6 for L = (0.8, 0.6, 0) over the floor y = 0; Kd = (0.5, 1, 0.25),
        // intensity (2, 1, 4): (2 * 0.5, 1 * 1, 4 * 0.25) * 0.6 = (0.6, 0.6, 0.6).
        blinn_phong_case(material(Color(0.0), {0.5, 1, 0.25}, Color(0.0), Color(0.0), 1.0),
                         lit_point(up, up), {{0.8, 0.6, 0}, 10.0, {2, 1, 4}}),
        // The highlight, seen from straight above: L + V = (0.8, 1.6, 0), of squared length 3.2,
        // so (N . H)^2 = 2.56 / 3.2 = 0.8 and (N . H)^4 = 0.64: Ks (0.64) = (0.64, 0.32, 0.16).
        // (Unnormalized, N . (L + V))^4 = 1.6^4 = 6.5536; Phong's (R . V)^4 = 0.6^4 = 0.1296.)
        blinn_phong_case(material(Color(0.0), Color(0.0), {1, 0.5, 0.25}, Color(0.0), 4.0),
                         lit_point(up, up), {{0.8, 0.6, 0}, 10.0, Color(1.0)}),
        // A light below the floor: N . L = -0.8, black, though N . H = 0.2 / sqrt(0.4) > 0
        // would show a highlight through the floor.
        blinn_phong_case(material(Color(0.0), Color(1.0), Color(1.0), Color(0.0), 1.0),
                         lit_point(up, up), {{0.6, -0.8, 0}, 10.0, Color(1.0)}),
        // Shininess 0: max(N . H, 0)^0 = 1, so the highlight is Ks wherever the light reaches:
        // 0.5 * 0.6 + (0.2, 0.4, 0.6) = (0.5, 0.7, 0.9).
        blinn_phong_case(material(Color(0.0), Color(0.5), {0.2, 0.4, 0.6}, Color(0.0), 0.0),
                         lit_point(up, up), {{0.8, 0.6, 0}, 10.0, Color(1.0)}),
        // The shading normal (0.6, 0.8, 0) points at the light: N . L = 1, I = Kd. By the
        // geometric normal, N . L would be 0.8.
        blinn_phong_case(material(Color(0.0), {0.5, 0.25, 1}, Color(0.0), Color(0.0), 1.0),
                         {{0, 0, 0}, {0, 0, 0}, up, {0.6, 0.8, 0}, up},
                         {{0.6, 0.8, 0}, 10.0, Color(1.0)}),
        // A + E + 0.5 * 1 * (1, 1, 1) + 0.5 * 0.6 * (0.5, 1, 2)
        // = (0.1, 0.35, 0.1) + (0.5, 0.5, 0.5) + (0.15, 0.3, 0.6) = (0.75, 1.15, 1.2).
        local_shading_case(mixed, lit_point(up, up),
                           {{up, 10.0, Color(1.0)}, {{0.8, 0.6, 0}, kInf, {0.5, 1, 2}}}),
        local_shading_case(no_light, lit_point(up, up), {}),
        spawn_case(wall, out, 3.0, along_ray(0.125)),
        // (-1, 4, 2) + 0.125 (-1, 0, 0) = (-1.125, 4, 2).
        spawn_case(wall, out, 3.0, along_normal(0.125)),
        // Through the wall: (-1, 4, 2) + 0.125 (1, 0, 0) = (-0.875, 4, 2).
        spawn_case(wall, back, 3.0, along_normal(0.125)),
        // In the tangent plane the normal as given: (-1.125, 4, 2) again.
        spawn_case(wall, along, 3.0, along_normal(0.125)),
        // d = 1 * 2e-15: x beyond -1 - 2e-15, and for the back beyond -1 + 2e-15.
        spawn_case(wall, out, 3.0, kErrorBound),
        spawn_case(wall, back, 3.0, kErrorBound),
        // 1000 times the error, 1000 times the offset: d = 2e-12.
        spawn_case(coarse_wall, out, 3.0, kErrorBound),
        // To a point light 2.5 away, and to a directional one, unbounded.
        shadow_case(wall, {out, 2.5, Color(1.0)}, kErrorBound),
        shadow_case(wall, {out, kInf, Color(1.0)}, along_normal(0.125)),
    };
}

// The hidden ones: the contract's edge cases a student's own tests may not reach.
std::vector<PublicCase> hidden_cases() {
    const Vec3 up{0, 1, 0};
    const Vec3 z{0, 0, 1};
    // N = (1, 0, 0), L = (0.6, 0.8, 0), V = (-0.6, 0, 0.8): L + V = (0, 0.8, 0.8), so N . H = 0
    // exactly while N . L = 0.6 (the geometric normal (0.6, 0, 0.8) faces the eye).
    const SurfacePoint grazing_half{{0, 0, 0}, {0, 0, 0}, {0.6, 0, 0.8}, {1, 0, 0}, {-0.6, 0, 0.8}};
    const Material matte_floor =
        material({0.05, 0.1, 0.15}, Color(1.0), Color(0.0), Color(0.0), 1.0);
    const SurfacePoint exact_point{{0, 2.5, -7}, {0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
    const SurfacePoint far_point{{1e6, 3, -2}, {1e-12, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
    const SurfacePoint oblique{
        {1e5, -2e5, 3e4}, {1e-10, 5e-11, 3e-10}, {0.6, 0, -0.8}, {0.6, 0, -0.8}, {0.6, 0, -0.8}};
    const SurfacePoint bent{{0.5, 0.5, 0}, {0, 0, 1e-12}, z, {0.6, 0, 0.8}, z};
    const SurfacePoint distant{
        {2e7, -1e7, 5e6}, Vec3(3e-9), {0.6, 0.8, 0}, {0.6, 0.8, 0}, {0.6, 0.8, 0}};
    SurfacePoint coarse_distant = distant;
    coarse_distant.error = Vec3(3e-6);
    const SurfacePoint ceiling{{3, -1, 0.5}, Vec3(1e-15), {0, 0, -1}, {0, 0, -1}, {0, 0, -1}};
    const SurfacePoint ledge{{0, 1, 0}, Vec3(1e-16), up, up, up};
    const SurfacePoint bent_away{{0, 0, 0}, {0, 0, 0}, up, {0.8, 0.6, 0}, {-0.96, 0.28, 0}};
    const SurfacePoint wall{{-1, 4, 2}, {2e-15, 0, 0}, {-1, 0, 0}, {-1, 0, 0}, {-0.6, 0, 0.8}};
    return {
        attenuation_case({0.5, 2, 3}, 0),
        // 1 + 0.5e6, exact.
        attenuation_case({1, 0.5, 0}, 1e6),
        // 5e160 away: its square overflows, its length must not (stage 1's length handles it).
        point_light_case({{0, 3e160, 4e160}, {0.25, 0.5, 1}, {1, 0, 0}}, {0, 0, 0}),
        // 5e-300 away: its square underflows to 0, its direction must not.
        point_light_case({{0, 3e-300, 4e-300}, {0.25, 0.5, 1}, {1, 0, 0}}, {0, 0, 0}),
        at_the_light_case({{1e10, -3, 0.5}, {1, 1, 1}, {0, 0, 1}}),
        // (-2, -2, 1) / 3.
        directional_light_case({{-2, -2, 1}, {0.7, 0.2, 0.1}}),
        // N . H = 0 exactly, shininess 0: 0^0 = 1, so I (Kd 0.6 + Ks)
        // = (1 (0.15 + 0.5), 2 (0.15 + 0.25), 0.5 (0.15 + 1)) = (0.65, 0.8, 0.575).
        blinn_phong_case(material(Color(0.0), Color(0.25), {0.5, 0.25, 1}, Color(0.0), 0.0),
                         grazing_half, {{0.6, 0.8, 0}, 10.0, {1, 2, 0.5}}),
        // A light behind, shininess 0: black, not Ks.
        blinn_phong_case(material(Color(0.0), Color(1.0), Color(1.0), Color(0.0), 0.0),
                         lit_point(z, z), {{0.28, 0, -0.96}, 10.0, Color(1.0)}),
        // The geometric normal sees the light (N . L = 0.28) but the shading normal does not
        // (0.6 * -0.96 + 0.8 * 0.28 = -0.352): black.
        blinn_phong_case(material(Color(0.0), Color(1.0), Color(1.0), Color(0.0), 8.0),
                         {{0, 0, 0}, {0, 0, 0}, up, {0.6, 0.8, 0}, up},
                         {{-0.96, 0.28, 0}, 10.0, Color(1.0)}),
        // A light exactly in the tangent plane, N . L = 0: black, though N . H = sqrt(0.5) would
        // show a highlight.
        blinn_phong_case(material(Color(0.0), Color(1.0), Color(1.0), Color(0.0), 1.0),
                         lit_point(up, up), {{1, 0, 0}, 10.0, Color(1.0)}),
        // The eye behind the shading normal (0.8, 0.6, 0), which the geometric normal (0, 1, 0)
        // faces: N . L = 0.352 but N . (L + V) = -0.248, so max(N . H, 0)^s = 0 and only the
        // diffuse term is left, 0.5 * 0.352 = 0.176. (N . H)^2 unclamped would add 0.02, and
        // (N . H)^0.5 is NaN.
        blinn_phong_case(material(Color(0.0), Color(0.5), Color(1.0), Color(0.0), 2.0), bent_away,
                         {{-0.28, 0.96, 0}, 10.0, Color(1.0)}),
        blinn_phong_case(material(Color(0.0), Color(0.5), Color(1.0), Color(0.0), 0.5), bent_away,
                         {{-0.28, 0.96, 0}, 10.0, Color(1.0)}),
        // The eye exactly opposite the light, L = -V = (0.96, -0.28, 0), which the shading
        // normal (0.8, 0.6, 0) sees (N . L = 0.6): L + V = 0 has no direction, N . H counts as 0.
        // Shininess 8: 0.5 * 0.6 = 0.3 and no highlight; shininess 0: 0^0 = 1, 0.3 + Ks.
        blinn_phong_case(material(Color(0.0), Color(0.5), Color(1.0), Color(0.0), 8.0), bent_away,
                         {{0.96, -0.28, 0}, 10.0, Color(1.0)}),
        blinn_phong_case(material(Color(0.0), Color(0.5), {0.25, 0.5, 0.75}, Color(0.0), 0.0),
                         bent_away, {{0.96, -0.28, 0}, 10.0, Color(1.0)}),
        // The eye in the mirror direction: H = N, (N . H)^1000 = 1; 0.5 * 0.8 + Ks.
        blinn_phong_case(material(Color(0.0), Color(0.5), {0.25, 0.5, 0.75}, Color(0.0), 1000.0),
                         lit_point(up, {-0.6, 0.8, 0}), {{0.6, 0.8, 0}, 10.0, Color(1.0)}),
        // A light behind the floor among the visible ones adds nothing: A + 0.5 + 0 + 0.1
        // + 0.6 (0.25, 0.5, 1) = (0.8, 1, 1.35).
        local_shading_case(matte_floor, lit_point(z, z),
                           {{z, 10.0, Color(0.5)},
                            {{0, 0.6, -0.8}, 10.0, Color(1.0)},
                            {{std::sqrt(3.0) / 2, 0, 0.5}, kInf, Color(0.2)},
                            {{0, 0.8, 0.6}, 5.0, {0.25, 0.5, 1}}}),
        // Tangent, on a ceiling facing down: (3, -1, 0.5) - 0.25 (0, 0, 1).
        spawn_case(ceiling, {0.6, 0.8, 0}, 2.0, along_normal(0.25)),
        spawn_case(ceiling, {0.6, 0, -0.8}, kInf, along_ray(1e-4)),
        // No rounding error at all (d = 0): the one-ulp step alone takes x off the plane x = 0.
        spawn_case(exact_point, {0.6, 0.8, 0}, 1.0, kErrorBound),
        // d = 1e-12 is below half an ulp of 1e6 (5.8e-11): P + d n rounds back to P, and only
        // the ulp step puts the origin beyond d.
        spawn_case(far_point, {0.8, 0.6, 0}, 1.0, kErrorBound),
        spawn_case(oblique, {0, 0.6, -0.8}, 1.0, kErrorBound),
        // The offset follows the geometric normal, not the shading one.
        spawn_case(bent, {0, 0.6, 0.8}, 1.0, kErrorBound),
        // x1000 error, x1000 offset, far from the origin: d = 1.4 * 3e-9 (ulps of 2e7 are 3.7e-9)
        // and 1.4 * 3e-6.
        spawn_case(distant, {0.6, 0.8, 0}, 1.0, kErrorBound),
        spawn_case(coarse_distant, {0.6, 0.8, 0}, 1.0, kErrorBound),
        // In the tangent plane the normal as given, (-1, 0, 0): x below -1 - 2e-15.
        spawn_case(wall, {0, 0.6, 0.8}, 1.0, kErrorBound),
        // A light below the ledge: the shadow ray starts below it, (0, 0.5, 0), and ends at the
        // light.
        shadow_case(ledge, {{0.6, -0.8, 0}, 4.0, Color(1.0)}, along_normal(0.5)),
        shadow_case(ledge, {{0.6, 0.8, 0}, kInf, Color(1.0)}, along_ray(0.5)),
    };
}

// The generated cases, each drawn from its own generator: the grader's from kOracleSeed, a
// release's sample from kOracleSeed + kSampleSeedOffset.
constexpr std::uint64_t kOracleSeed = 0x5EED'0006;

// Each channel uniform in [0, high).
Color random_colour(PortableRandom& random, double high) {
    return {random.uniform(0, high), random.uniform(0, high), random.uniform(0, high)};
}

Material random_material(PortableRandom& random) {
    const double shininess[] = {0, 0.5, 1, 2.5, 10, 64, 200};
    const Color ambient = random_colour(random, 0.3);
    const Color diffuse = random_colour(random, 1);
    const Color specular = random_colour(random, 1);
    const Color emission = random.unit() < 0.3 ? random_colour(random, 0.5) : Color(0.0);
    return material(ambient, diffuse, specular, emission, shininess[random.integer(0, 6)]);
}

// A light seen from a random point on a surface: a quarter of them behind it, none within 1e-3
// of the tangent plane (where a rounding decides between lit and black) and no half vector
// within 1e-3 of it either.
struct LitScene {
    SurfacePoint point;
    LightSample light;
};

LitScene random_lit(PortableRandom& random) {
    for (;;) {
        const Vec3 n = random.unit_vector();
        const Vec3 l = random.unit_vector();
        const Vec3 v = random.unit_vector();
        const double n_dot_l = glm::dot(n, l);
        const Vec3 sum = l + v;
        if (glm::dot(n, v) < 0.05 || std::abs(n_dot_l) < 1e-3 || glm::length(sum) < 1e-3) continue;
        if (n_dot_l < 0 && random.unit() < 0.67) continue;
        if (n_dot_l > 0 && glm::dot(n, glm::normalize(sum)) < 1e-3) continue;
        const Vec3 position = random.point(10);
        const double distance = 1 + 10 * random.unit();
        return {{position, Vec3(0.0), n, n, v}, {l, distance, random_colour(random, 2)}};
    }
}

PublicCase random_attenuation_case(PortableRandom& random) {
    const Attenuation a{random.unit(), random.unit(), random.unit()};
    return attenuation_case(a, 100 * random.unit());
}

PublicCase random_point_light_case(PortableRandom& random) {
    const double scale = random.decade(-2, 4);
    const Vec3 light = random.point(scale);
    const Vec3 point = light + scale * random.uniform(0.01, 1) * random.unit_vector();
    const Color colour = random_colour(random, 2);
    const Attenuation attenuation{0.1 + random.unit(), random.unit(), random.unit()};
    return point_light_case({light, colour, attenuation}, point);
}

PublicCase random_blinn_phong_case(PortableRandom& random) {
    const LitScene s = random_lit(random);
    return blinn_phong_case(random_material(random), s.point, s.light);
}

PublicCase random_local_shading_case(PortableRandom& random) {
    const LitScene s = random_lit(random);
    std::vector<LightSample> lights{s.light};
    const std::int64_t more = random.integer(0, 3);
    for (std::int64_t i = 0; i < more; ++i) {
        // More lights at the same point: keep the point, take the other lights.
        LitScene other = random_lit(random);
        while (std::abs(glm::dot(s.point.shading_normal, other.light.direction)) < 1e-3 ||
               glm::dot(s.point.shading_normal,
                        glm::normalize(other.light.direction + s.point.to_eye)) < 1e-3) {
            other = random_lit(random);
        }
        lights.push_back(other.light);
    }
    return local_shading_case(random_material(random), s.point, lights);
}

// Points at scales 1e-3 to 1e7, with errors from none to 1e4 ulps of their size (and to ulps of
// a larger scene), directions at least 0.05 off the tangent plane; case k picks the rule and
// whether it asks spawn_ray or shadow_ray.
PublicCase random_leaving_case(PortableRandom& random, int k) {
    const double scale = std::pow(10.0, static_cast<double>(random.integer(-3, 7)));
    SurfacePoint p;
    p.position = random.point(100 * scale);
    const double size =
        std::max({std::abs(p.position.x), std::abs(p.position.y), std::abs(p.position.z)});
    const double error_scale = k % 10 == 0 ? 0.0 : std::ldexp(size, -52) * random.decade(0, 4);
    p.error = random_colour(random, error_scale);
    p.normal = random.unit_vector();
    p.shading_normal = glm::normalize(p.normal + 0.3 * random.unit_vector());
    p.to_eye = p.normal;
    Vec3 direction = random.unit_vector();
    while (std::abs(glm::dot(direction, p.normal)) < 0.05)
        direction = random.unit_vector();
    const RayOffset offset = k % 3 == 1 ? along_normal(scale * random.decade(-4, 0)) : kErrorBound;
    if (k % 4 != 3) return spawn_case(p, direction, 1 + random.unit(), offset);
    const double distance = k % 8 == 3 ? kInf : scale * random.unit();
    return shadow_case(p, {direction, distance, Color(1.0)},
                       k % 3 == 2 ? along_ray(1e-3 * scale) : offset);
}

// Appends `count` cases, the k-th (k from 0) made by `make(random, k)` from
// PortableRandom(seed, i), i the index the case gets in `cases`, so that `--case i` rebuilds
// that case alone on any platform.
template <typename Make>
void add_seeded(std::vector<PublicCase>& cases, std::uint64_t seed, int count, Make make) {
    for (int k = 0; k < count; ++k) {
        PortableRandom random(seed, cases.size());
        cases.push_back(make(random, k));
    }
}

// The generated cases, drawn from `seed`: `count` attenuations, twice as many point lights and
// local sums, three times as many Blinn-Phong terms, six times as many rays leaving a surface.
std::vector<PublicCase> generated_cases(std::uint64_t seed, int count) {
    std::vector<PublicCase> cases;
    add_seeded(cases, seed, count,
               [](PortableRandom& r, int) { return random_attenuation_case(r); });
    add_seeded(cases, seed, 2 * count,
               [](PortableRandom& r, int) { return random_point_light_case(r); });
    add_seeded(cases, seed, 3 * count,
               [](PortableRandom& r, int) { return random_blinn_phong_case(r); });
    add_seeded(cases, seed, 2 * count,
               [](PortableRandom& r, int) { return random_local_shading_case(r); });
    add_seeded(cases, seed, 6 * count, random_leaving_case);
    return cases;
}

std::vector<ProbeCase> oracle_cases() {
    return data_judged_cases(generated_cases(kOracleSeed, 50));
}

}  // namespace

PublicCheck stage6_public_check() {
    return {"stage6.unit", 6, "unit", kPublicName, public_cases()};
}

PublicCheck stage6_sample_check() {
    return sample_check(6, "lights, shading and spawned rays on random inputs against long double",
                        generated_cases(kOracleSeed + kSampleSeedOffset, 2));
}

std::vector<CheckDefinition> stage6_checks() {
    return stage_case_checks(
        {6, kPublicName, [] { return data_judged_cases(public_cases()); },
         "shading and ray offsets on the contract's edge cases",
         [] { return data_judged_cases(hidden_cases()); },
         "lights, shading and spawned rays on random inputs against long double", oracle_cases});
}

}  // namespace raystep::grade
