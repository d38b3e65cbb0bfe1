#pragma once

#include <vector>

#include "app/grade/public_case.h"
#include "base/math/portable_random.h"

namespace raystep::grade {

// Stage 9's radiance_with_refraction cases (stage9_radiance_cases.cpp): the recursion over fake
// scenes played inside the probe, whose hits are keyed by the ray that should reach them
// (grading/9_refraction/refraction_calls.cpp), each case's colour and rays decided in long double
// (grading/9_refraction/refraction_oracle.h) and judged by "refraction_radiance"
// (grading/9_refraction/refraction_judges.h).

/// Hand-worked scenes: glass head-on, total internal reflection, a nested solid.
std::vector<PublicCase> stage9_public_radiance_cases();

/// The contract's edges: F applied once, the media passed down and kept for reflected rays,
/// bounces cut, black weights tracing nothing, Schlick leaving glass.
std::vector<PublicCase> stage9_hidden_radiance_cases();

/// Leaving a solid that is in the stack twice, with another solid entered between: its latest
/// entry goes, so the ray travels on in the solid between.
std::vector<PublicCase> stage9_latest_entry_radiance_cases();

/// Hits whose shading normal is bent from the geometric one: F from V . N with the shading
/// normal, exact and Schlick, entering and leaving glass.
std::vector<PublicCase> stage9_shading_normal_radiance_cases();

/// Head-on hits where V . N rounds above 1 (V = N = normalize(1, 1, 1)): exact and Schlick,
/// entering and leaving glass; no NaN.
std::vector<PublicCase> stage9_cosine_above_one_radiance_cases();

/// A unit vector whose dot product with itself rounds to 1 + 2^-52 in double, in any order of
/// the sum: normalize(1, 1, 1).
Vec3 unit_vector_squaring_above_one();

/// A random tree of glass and mirrors, drawn from `random`; `k` cycles the offset rules and the
/// Fresnel form.
PublicCase stage9_random_radiance_case(PortableRandom& random, int k);

}  // namespace raystep::grade
