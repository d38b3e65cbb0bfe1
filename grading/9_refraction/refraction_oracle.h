#pragma once

// Stage 9's expectations in long double: Snell's law, the Fresnel reflectances, the media a ray
// is in, the refracted ray, and radiance_with_refraction over a fake scene. No CGAL: square
// roots, quotients and sums of products, each with the rounding budget of a right formula in
// double stated where it is computed (refraction_oracle.cpp).

#include <functional>
#include <optional>
#include <vector>

#include "app/grade/expected_ray.h"
#include "base/scene/ray_offset.h"
#include "grader/oracle/wide_vec.h"
#include "grading/9_refraction/refraction_calls.h"
#include "stages/2_rays/ray.h"
#include "stages/6_shading/shading.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

/// What a right answer may be where total internal reflection is in question: a direction, no
/// direction (nullopt), or either, when the case lies within rounding of the critical angle.
enum class RefractionAnswer { direction, none, either };

/// refract(incident, normal, eta) as the oracle decides it: with incident and normal normalized
/// in long double, sin^2(theta2) = eta^2 (1 - cos^2(theta1)) against 1 within the rounding budget
/// of a double; the exact unit direction (the grazing one, cos(theta2) = 0, where the case is
/// within rounding of the critical angle on the far side), and the per-component tolerance of a
/// right formula in double.
struct ExpectedRefraction {
    RefractionAnswer answer = RefractionAnswer::direction;
    WideVec direction{0};
    Wide tolerance = 0;
};

ExpectedRefraction expected_refraction(const Vec3& incident, const Vec3& normal, double eta);

/// A number and how far a right formula in double may land from it.
struct ExpectedNumber {
    Wide value = 0;
    Wide tolerance = 0;
};

/// fresnel_exact(cos_incident, n1, n2): the mean of the s and p reflectances, 1 beyond the
/// critical angle; the tolerance spans every right form's answers over its rounding: the cosine
/// form's over both cosines, the sine-and-tangent form's over both angles.
ExpectedNumber expected_fresnel_exact(double cos_incident, double n1, double n2);

/// fresnel_schlick(cos_incident, n1, n2), with the cosine on the less dense side.
ExpectedNumber expected_fresnel_schlick(double cos_incident, double n1, double n2);

/// refracted_ray(point, n1, n2, offset): nullopt under total internal reflection (`answer`
/// none), else the ray along refract(-V, N, n1 / n2) leaving by the offset's rule towards the far
/// side, unbounded; `either` within rounding of the critical angle, where the ray, if any, is
/// judged as `ray` says.
struct ExpectedRefractedRay {
    RefractionAnswer answer = RefractionAnswer::direction;
    grade::ExpectedRay ray{};
};

ExpectedRefractedRay expected_refracted_ray(const SurfacePoint& point, double n1, double n2,
                                            const RayOffset& offset);

/// The contract's current_index and after_crossing, written from the header's words, for the
/// fake scenes' media (the named media cases state their answers as literals).
double expected_current_index(const MediumStack& inside);
MediumStack expected_after_crossing(const MediumStack& inside, const Medium& solid, bool entering);

/// One hit of a fake scene: the probe's shade answers it for a ray that starts near `key`'s
/// origin and runs along `key`'s direction (grading/9_refraction/refraction_calls.cpp says how
/// near).
using probe::KeyedHit;

/// What the fake scene holds where a ray lands, asked once for each ray radiance_with_refraction
/// should trace, with the media that ray is in: a hit, or nullopt for a miss. Case makers answer
/// from a list or a generator.
using HitMaker = std::function<std::optional<MediumHit>(const Ray& key, const MediumStack& inside)>;

/// radiance_with_refraction over the scene `make` builds: the colour and its tolerance, every ray
/// the recursion should trace (in any order), and the scene as the probe must be given it.
struct ExpectedRefractionRadiance {
    WideVec colour{0};
    WideVec colour_tolerance{0};
    std::vector<grade::ExpectedRay> rays;
    std::vector<KeyedHit> scene;
};

/// Throws std::logic_error where a right answer is not one: a hit within rounding of the critical
/// angle, or a reflected weight Ks + Kt F with Ks black and F within rounding of 0 (traced or not
/// depends on rounding). Case makers keep away from both.
ExpectedRefractionRadiance expected_radiance_with_refraction(const HitMaker& make, const Ray& eye,
                                                             int bounces, const MediumStack& inside,
                                                             bool schlick, const RayOffset& offset);

}  // namespace raystep
