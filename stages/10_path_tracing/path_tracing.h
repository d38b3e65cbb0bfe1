#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "base/math/random_stream.h"
#include "base/scene/scene.h"
#include "stages/1_vectors/vectors.h"
#include "stages/2_rays/ray.h"
#include "stages/6_shading/shading.h"

namespace raystep {

// Stage 10: path tracing. Handout: docs/stage10.md.
//
// The rendering equation (Kajiya, 1986) says what a point sends towards the eye:
//
//   L(x, wo) = Le(x, wo) + integral over the hemisphere of f(x, wi, wo) L(x', -wi) cos(theta_i) dwi
//
// where x' is the point the ray from x along wi meets. Stage 8 estimated the direct part of it
// by sampling the lights. A path tracer estimates all of it by Monte Carlo: at each hit it draws
// one direction wi with a known density p(wi), and carries on with the weight f cos / p. The
// estimate is right on average whatever p is, provided p > 0 wherever the integrand is not
// zero; a p shaped like the integrand makes it less noisy.
//
// Directions are drawn in a local frame whose z axis is the normal (or a lobe's axis), then
// turned into the world by frame_around. Random numbers come only from the Vec2 `u` (uniform in
// [0, 1)^2) a caller hands in, or in path_radiance from its RandomStream.

// --- Sampling the hemisphere (hemisphere.cpp) ----------------------------------------------

/// A frame whose w is the unit vector `n`: stage 1's orthonormal_frame(n, b) with b the
/// coordinate axis least aligned with n, so that b is never parallel to n.
Frame frame_around(const Vec3& n);

/// The local direction (x, y, z) in the world: x u + y v + z w.
Vec3 to_world(const Frame& frame, const Vec3& local);

/// A world direction in the frame: (d . u, d . v, d . w).
Vec3 to_local(const Frame& frame, const Vec3& world);

/// A direction uniform over the hemisphere z >= 0: cos(theta) = u.x, phi = 2 pi u.y.
Vec3 uniform_hemisphere(const Vec2& u);

/// Its density over solid angle: 1 / (2 pi) for z >= 0, 0 below.
double uniform_hemisphere_pdf(const Vec3& direction);

/// A direction over z >= 0 with density cos(theta) / pi: a point uniform on the unit disk (r =
/// sqrt(u.x), phi = 2 pi u.y) lifted onto the hemisphere, z = sqrt(1 - r^2) (Malley's method).
Vec3 cosine_hemisphere(const Vec2& u);

/// Its density: max(z, 0) / pi.
double cosine_hemisphere_pdf(const Vec3& direction);

/// A direction around the z axis with density (s + 1) / (2 pi) cos^s(alpha), alpha its angle
/// to z: cos(alpha) = u.x^(1 / (s + 1)), phi = 2 pi u.y. The Phong lobe's shape for s > 0;
/// cosine sampling's for s = 1.
Vec3 phong_lobe(const Vec2& u, double exponent);

/// Its density: (s + 1) / (2 pi) z^s for z >= 0, and 0 below, even for s = 0.
double phong_lobe_pdf(const Vec3& direction, double exponent);

/// GGX's (Trowbridge-Reitz's) distribution of microfacet normals of roughness alpha > 0:
///
///   D(h) = alpha^2 / (pi cos^4(theta_h) (alpha^2 + tan^2(theta_h))^2)   for h.z > 0, else 0,
///
/// h a unit vector. Finite wherever h.z > 0, for every alpha whose square is a normal number.
double ggx_distribution(const Vec3& half_vector, double roughness);

/// A microfacet normal h with density D(h) cos(theta_h) over solid angle:
/// theta_h = atan(alpha sqrt(u.x) / sqrt(1 - u.x)), phi = 2 pi u.y.
Vec3 ggx_half_vector(const Vec2& u, double roughness);

/// Its density: D(h) max(h.z, 0).
double ggx_half_vector_pdf(const Vec3& half_vector, double roughness);

// --- The BRDF (brdf.cpp) ----------------------------------------------------------------------

/// The BRDF of a surface, as a scene's `brdf` (base/scene/scene.h's BrdfModel), `diffuse`,
/// `specular`, `shininess` and `roughness` set it.
struct SurfaceBrdf {
    BrdfModel model = BrdfModel::phong;
    Color diffuse{0.0};    ///< Kd
    Color specular{0.0};   ///< Ks
    double shininess = 0;  ///< s, the Phong lobe's exponent
    double roughness = 0;  ///< alpha, GGX's roughness
};

/// f(wi, wo) at a point of unit normal n, wi towards the light and wo towards the eye (both
/// unit), zero unless both are above the surface (n . wi > 0 and n . wo > 0):
/// - phong: Kd / pi + Ks (s + 2) / (2 pi) (r . wi)^s where r . wi > 0 and 0 elsewhere, even
///   for s = 0, as phong_lobe_pdf; r = reflect(-wo, n) the mirror direction;
/// - ggx: Kd / pi + F G D / (4 (n . wi)(n . wo)), with h = normalize(wi + wo), D =
///   ggx_distribution(h in n's frame, alpha), Schlick's F = Ks + (1 - Ks)(1 - wi . h)^5 and
///   Smith's G = G1(wi) G1(wo), G1(w) = 2 / (1 + sqrt(1 + alpha^2 tan^2(theta_w))).
Color evaluate_brdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_light,
                    const Vec3& to_eye);

// --- Importance sampling the BRDF (brdf_sampling.cpp) ---------------------------------------

/// How often sample_brdf draws from the specular lobe rather than the diffuse one:
/// t = mean(Ks) / (mean(Kd) + mean(Ks)), for GGX at least 0.25 (its lobe is sharp even where Ks
/// is dim); 0 for a black Phong surface.
double specular_probability(const SurfaceBrdf& brdf);

/// A direction wi towards the light, drawn with probability 1 - t by cosine_hemisphere about n,
/// and with probability t from the specular lobe: phong_lobe about r = reflect(-wo, n), or for
/// GGX wo reflected about ggx_half_vector about n. `choice` (uniform in [0, 1)) picks the lobe:
/// specular when choice < t. wi may fall below the surface; evaluate_brdf is zero there.
Vec3 sample_brdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_eye, const Vec2& u,
                 double choice);

/// The density of sample_brdf's wi over solid angle: (1 - t) cos(theta_i) / pi plus t times
/// the lobe's density, for GGX ggx_half_vector_pdf(h) / (4 |wi . h|), h = normalize(wi + wo)
/// turned to n's side (h and -h reflect wo to the same wi).
double brdf_pdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_eye,
                const Vec3& to_light);

// --- Next event estimation (light_sampling.cpp) --------------------------------------------

/// A point of a quad light, seen from a point of the scene, as a path tracer samples it: the
/// unit direction to it, its distance, the density of that direction over solid angle, and the
/// radiance it sends back along it (the light's radiance on its emitting side, ac x ab; black
/// from behind).
struct LightDirectionSample {
    Vec3 direction;
    double distance = 0;
    double pdf = 0;
    Color radiance{0.0};
};

/// The point y = a + u.x ab + u.y ac, uniform over the light's area A: its density over solid
/// angle is d^2 / (A |cos(theta_l)|), theta_l the angle at y between the light's normal and the
/// direction back to `point`. Where `point` lies on the light's plane, or is y, no direction
/// carries light from y to it: the sample is black, with density 0.
LightDirectionSample sample_light_direction(const QuadLight& light, const Vec3& point,
                                            const Vec2& u);

/// The density with which sample_light_direction, from `point`, gives the unit `direction`:
/// d^2 / (A |cos(theta_l)|) where the ray from `point` along it meets the light (at distance d),
/// 0 where it misses.
double light_direction_pdf(const QuadLight& light, const Vec3& point, const Vec3& direction);

// --- Combining estimators (estimators.cpp) ----------------------------------------------------

/// Veach's balance heuristic for one sample of each of two strategies: the weight of a sample
/// drawn with density `pdf`, where the other strategy would have drawn it with `other_pdf`:
/// pdf / (pdf + other_pdf); 0 when both are 0.
double balance_heuristic(double pdf, double other_pdf);

/// Veach's power heuristic, exponent 2: pdf^2 / (pdf^2 + other_pdf^2); 0 when both are 0.
double power_heuristic(double pdf, double other_pdf);

/// Russian roulette: a path whose weight is `throughput` goes on with probability
/// q = min(1, max component of the throughput). Returns the weight it goes on with, throughput
/// / q, when u < q; nullopt when it stops. Unbiased: the expected weight is the throughput.
std::optional<Color> russian_roulette(const Color& throughput, double u);

// --- The path (path.cpp) -----------------------------------------------------------------------

/// What a path meets where a ray first hits the scene.
struct PathHit {
    SurfacePoint point;  ///< stage 6's point: position, normals facing the ray, to_eye
    SurfaceBrdf brdf;
    Color emission{0.0};  ///< the radiance the surface sends back along the ray
    /// Which of PathScene::lights the surface is, which next event estimation also reaches;
    /// nullopt for any other surface, emitting or not.
    std::optional<std::size_t> light;
};

/// The scene as a path sees it: `intersect` finds the nearest hit, the lights' too; `occluded`
/// tells whether a surface blocks a shadow ray, the lights' never (they cast no shadow).
struct PathScene {
    std::function<std::optional<PathHit>(const Ray&)> intersect;
    std::function<bool(const Ray&)> occluded;
    std::vector<QuadLight> lights;
    RayOffset offset;  ///< how rays leave a surface (stage 6's spawn_ray)
};

// How a path draws its next direction and reaches the lights are the scene's
// `importancesampling` and `nexteventestimation`: DirectionSampling and NextEvent in
// base/scene/scene.h.

struct PathSettings {
    int max_depth = 5;  ///< the most bounces: hits whose reflected light the path counts; -1: no
                        ///< limit
    bool russian_roulette = false;
    DirectionSampling sampling = DirectionSampling::cosine;
    NextEvent next_event = NextEvent::off;
};

/// An estimate of the radiance L coming back along `ray`: one path, extended hit by hit, its
/// throughput (the product of f cos / p so far) starting at 1.
/// - At each hit the path takes the throughput times the surface's emission, except where next
///   event estimation has counted that light already: after the first hit, a light of
///   PathScene::lights adds nothing with `on`, and with `mis` its emission weighted by the
///   power heuristic of the direction's density against light_direction_pdf from the last hit.
/// - Then, while bounces remain: with next event estimation, one sample of each light, tested
///   by `occluded` on stage 6's shadow_ray towards it, adds throughput f cos Le / p (with `mis`
///   times the power heuristic of p against the density `settings.sampling` would draw that
///   direction with); a sample of density 0 adds nothing. Then the path draws wi by
///   `settings.sampling` (uniform_hemisphere or cosine_hemisphere in n's frame_around, or
///   sample_brdf) and the throughput takes f cos / p. A wi below the surface ends the path.
///   Where Russian roulette is on, it is played with the new throughput, and the path ends
///   where it says so.
/// n is the point's shading normal throughout.
/// - It ends when a ray leaves the scene.
/// max_depth 0 is the emission the eye sees, 1 adds direct light. Throws std::domain_error when
/// max_depth is -1 and Russian roulette is off: such a path need not end.
Color path_radiance(const Ray& ray, const PathScene& scene, const PathSettings& settings,
                    RandomStream& random);

}  // namespace raystep
