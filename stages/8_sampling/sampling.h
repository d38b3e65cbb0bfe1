#pragma once

#include <functional>
#include <vector>

#include "base/math/random_stream.h"
#include "base/scene/scene.h"
#include "stages/2_rays/camera.h"
#include "stages/6_shading/shading.h"

namespace raystep {

// Stage 8: distribution ray tracing. Handout: docs/stage8.md.
//
// One ray per pixel sees one point of the pixel and one point of each light: edges alias and
// shadows are hard. Distribution ray tracing averages many rays, each sent through a different
// point, and places the points so that few of them cover the domain evenly: the unit square
// [0, 1)^2 is cut into n x n strata, and each sample is a random point of its own stratum
// (jittering). The same samples serve the pixel (antialiasing) and an area light (soft shadows).
//
// Random numbers come only from the RandomStream the caller hands in: a render is then the same
// for any thread count, and a grader can compare your samples with what a seed implies. Draw
// them from that stream itself, never from a copy of it: a caller may hand the same stream on to
// its next call (a pixel's film points, then each film sample's light samples in turn) and must
// get new numbers there.

/// The n x n jittered samples of [0, 1)^2: for each stratum [a/n, (a+1)/n) x [b/n, (b+1)/n),
/// a, b in [0, n), one point uniform in it. n^2 points in any order. Throws std::domain_error
/// unless n >= 1.
std::vector<Vec2> jittered_samples(int strata_per_side, RandomStream& random);

/// The centres of the same n x n strata, ((a + 1/2)/n, (b + 1/2)/n): supersampling with no
/// randomness. Throws std::domain_error unless n >= 1.
std::vector<Vec2> regular_samples(int strata_per_side);

/// `count` points uniform in [0, 1)^2, independent of one another. Throws std::domain_error
/// unless count >= 1.
std::vector<Vec2> random_samples(int count, RandomStream& random);

/// `count` samples placed by `pattern`: jittered and regular need count = n^2 and throw
/// std::domain_error otherwise.
std::vector<Vec2> samples(SamplePattern pattern, int count, RandomStream& random);

/// The ray from the eye through the point `film` of the image plane, in pixel coordinates:
/// film = (i + 0.5, j + 0.5) is the centre of pixel (i, j), and gives stage 2's
/// perspective_ray(camera, i, j). Unit direction, t in [0, infinity).
Ray perspective_ray_through(const PerspectiveCamera& camera, const Vec2& film);

/// The orthographic ray through `film`, as stage 2's orthographic_ray at pixel centres.
Ray orthographic_ray_through(const OrthographicCamera& camera, const Vec2& film);

/// What the camera sees through a point of the film (pixel coordinates): the renderer's ray
/// through it, traced and shaded.
using FilmRadiance = std::function<Color(const Vec2& film)>;

/// The colour of pixel (i, j): the mean of `radiance` over `count` points of the pixel, the
/// point (i + x, j + y) for each sample (x, y) that `samples(pattern, count, random)` gives
/// (a box filter over the pixel).
Color pixel_colour(const FilmRadiance& radiance, int i, int j, SamplePattern pattern, int count,
                   RandomStream& random);

/// The point y = a + u.x ab + u.y ac of a quad light, seen from `point` as a point light for
/// stage 6: L towards y, the distance |y - point|, and the intensity that makes the mean over
/// `sample_count` such samples the light's contribution:
///
///   intensity = radiance A cos(theta_l) / (pi d^2 sample_count),
///
/// A = |ab x ac| the light's area, theta_l the angle at y between the light's emitting side
/// (ac x ab) and the direction back to the point, cos(theta_l) taken as 0 behind the light. The
/// 1/pi makes Kd the diffuse albedo: a diffuse surface under a light of radiance L covering its
/// whole sky reflects Kd L. Throws std::domain_error when the point is on the light's plane at y
/// (no direction to it).
LightSample sample_quad_light(const QuadLight& light, const Vec3& point, const Vec2& u,
                              int sample_count);

/// True when something blocks the shadow ray.
using OccludedFunction = std::function<bool(const Ray&)>;

/// What a quad light adds at a point: over `sample_count` light samples placed on the light by
/// `samples(pattern, sample_count, random)`, the sum of stage 6's blinn_phong for each sample
/// that a shadow ray (stage 6's shadow_ray with `offset`) reaches. Samples behind the surface
/// add nothing and need no shadow ray.
Color quad_light_shading(const Material& material, const SurfacePoint& point,
                         const QuadLight& light, SamplePattern pattern, int sample_count,
                         RandomStream& random, const OccludedFunction& occluded,
                         const RayOffset& offset);

}  // namespace raystep
