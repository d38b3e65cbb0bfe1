#pragma once

#include <optional>

#include "base/math/types.h"
#include "base/scene/scene.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep::grade {

// Stage 10's oracle (path_tracing_oracle.cpp): each formula of the contract in long double, from
// the contract's words rather than the reference's code, and the closed forms the grader holds
// the path tracer's means to. A right formula in double lands within kPathRelativeTolerance of
// these, relative to the value (the cases keep away from the contract's few ill-conditioned
// places, which the hidden cases visit with tolerances of their own).

/// 1e-10: the formulas in double round to a few ulps, and pow(x, s) adds s ulps of x; the
/// generated cases keep s below 300 and x above 1e-3, so a right answer is within 1e-11.
inline constexpr double kPathRelativeTolerance = 1e-10;

/// The tolerance of an expected value: kPathRelativeTolerance of its size, and 1e-300 at least.
double path_tolerance(double expected);

double expected_uniform_hemisphere_pdf(const Vec3& direction);
double expected_cosine_hemisphere_pdf(const Vec3& direction);
double expected_phong_lobe_pdf(const Vec3& direction, double exponent);
double expected_ggx_distribution(const Vec3& half_vector, double roughness);
double expected_ggx_half_vector_pdf(const Vec3& half_vector, double roughness);

/// The contract's local samplers: cos(theta) and phi = 2 pi u.y as the header gives them.
Vec3 expected_uniform_hemisphere(const Vec2& u);
Vec3 expected_cosine_hemisphere(const Vec2& u);
Vec3 expected_phong_lobe(const Vec2& u, double exponent);
Vec3 expected_ggx_half_vector(const Vec2& u, double roughness);

Color expected_brdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_light,
                    const Vec3& to_eye);
double expected_specular_probability(const SurfaceBrdf& brdf);
double expected_brdf_pdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_eye,
                         const Vec3& to_light);

/// sample_light_direction's answer; light_direction_pdf's.
LightDirectionSample expected_light_direction(const QuadLight& light, const Vec3& point,
                                              const Vec2& u);
double expected_light_direction_pdf(const QuadLight& light, const Vec3& point,
                                    const Vec3& direction);

double expected_balance_heuristic(double pdf, double other_pdf);
double expected_power_heuristic(double pdf, double other_pdf);
std::optional<Color> expected_russian_roulette(const Color& throughput, double u);

// --- closed forms for the path tracer's means

/// The white furnace: radiance L_e (1 + a + ... + a^d) inside a closed diffuse sphere of albedo
/// a emitting L_e, d = max_depth; L_e / (1 - a) for d = -1 (a < 1 in every channel).
Color furnace_radiance(const Color& emission, const Color& albedo, int max_depth);

/// The radiance a floor point sends towards `to_eye` under one quad light and nothing else:
/// the integral over the light's area of f(wi, wo) L_e cos(theta_i) cos(theta_l) / d^2, by
/// Gauss-Legendre quadrature fine enough that its error is below 1e-9 of the value for the
/// grader's lights and lobes (path_tracing_oracle_test.cpp holds it to Lambert's form factor
/// for a diffuse floor). Black where the light shows the point its back.
Color floor_radiance(const SurfaceBrdf& brdf, const Vec3& point, const Vec3& normal,
                     const Vec3& to_eye, const QuadLight& light);

/// Lambert's form factor from a point of unit normal `normal` to the light's parallelogram (the
/// whole of it above the point's plane): (1 / 2 pi) sum over its edges of the angle each
/// subtends times the cosine of its plane with the normal.
double form_factor(const Vec3& point, const Vec3& normal, const QuadLight& light);

}  // namespace raystep::grade
