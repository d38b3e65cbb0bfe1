#pragma once

#include <string>
#include <vector>

#include "base/scene/scene.h"
#include "grading/8_sampling/sampling_calls.h"
#include "stages/6_shading/shading.h"

namespace raystep::grade {

// Stage 8's shadow rays as the probe hands them back (grading/8_sampling/sampling_calls.h): every
// ray quad_light_shading traced, in order, and what the probe's blocker answered for it. The grader
// takes the work and the colour from them, never from a figure the probe reports (student code
// runs in the probe's process and could write any): it finds each ray's light sample on the
// light, checks the blocker's answer with its own test, counts the rays sent to samples behind
// the surface, and adds up the colour the samples that got through make, which the student's
// colour must be.

using probe::Parallelogram;
using probe::TracedShadowRay;

/// One quad_light_shading call as the grader asked it.
struct QuadLightCall {
    Material material;
    SurfacePoint point;
    QuadLight light;
    int sample_count = 1;
    RayOffset offset;
    std::vector<Parallelogram> blockers;
};

/// What the grader reads from one call's shadow rays.
struct ShadowRayReading {
    /// The first ray that is no shadow ray from the point to the light, or whose blocker's
    /// answer the grader's own test contradicts; empty when there is none.
    std::string problem;
    std::vector<Vec2> samples;  ///< each ray's light sample u, where it meets the light
    int behind = 0;             ///< rays traced to samples behind the surface (N . L <= 0)
    Color colour{0.0};          ///< the sum of the blinn_phong terms of the samples that got
                                ///< through, each over the sample count, in long double
    Color tolerance{0.0};       ///< how far a right sum in double may be from it
};

/// Reads `rays` as the shadow rays of `call`. A ray is a shadow ray when its direction is unit,
/// its origin within the offset rule's reach of the point, and the line from the point along it
/// meets the light's parallelogram no later than the ray ends.
ShadowRayReading read_shadow_rays(const QuadLightCall& call,
                                  const std::vector<TracedShadowRay>& rays);

/// Empty when `colour` is the colour the rays explain, `expected` within `tolerance` in each
/// channel; else what differs. Written so that a NaN differs.
std::string colour_problem(const Color& colour, const Color& expected, const Color& tolerance);

}  // namespace raystep::grade
