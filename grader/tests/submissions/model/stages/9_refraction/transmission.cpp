// Stage 9: the refracted ray, and radiance through mirrors and glass. Handout: docs/stage9.md.

#include <limits>

#include "stages/1_vectors/vectors.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

std::optional<Ray> refracted_ray(const SurfacePoint& point, double n1, double n2,
                                 const RayOffset& offset) {
    const std::optional<Vec3> direction = refract(-point.to_eye, point.shading_normal, n1 / n2);
    if (!direction) return std::nullopt;
    return spawn_ray(point, *direction, std::numeric_limits<double>::infinity(), offset);
}

Color radiance_with_refraction(const MediumShadeFunction& shade, const Ray& ray, int bounces_left,
                               const MediumStack& inside, bool schlick, const RayOffset& offset) {
    const std::optional<MediumHit> hit = shade(ray);
    if (!hit) return Color(0.0);
    const SurfacePoint& point = hit->shaded.point;
    Color colour = hit->shaded.local;
    if (bounces_left <= 0) return colour;

    const Color black(0.0);
    double fresnel = 0.0;
    std::optional<Ray> through;
    MediumStack beyond = inside;
    if (hit->transmission != black) {
        beyond = after_crossing(inside, hit->solid, hit->entering);
        const double n1 = current_index(inside);
        const double n2 = current_index(beyond);
        const double cos1 = dot(point.to_eye, point.shading_normal);
        fresnel = schlick ? fresnel_schlick(cos1, n1, n2) : fresnel_exact(cos1, n1, n2);
        through = refracted_ray(point, n1, n2, offset);
        // No way through: everything the glass would pass on is reflected.
        if (!through) fresnel = 1.0;
    }

    const Color mirror = hit->shaded.reflectance + fresnel * hit->transmission;
    if (mirror != black) {
        colour += mirror * radiance_with_refraction(shade, reflected_ray(point, offset),
                                                    bounces_left - 1, inside, schlick, offset);
    }
    const Color glass = (1.0 - fresnel) * hit->transmission;
    if (through && glass != black) {
        colour += glass * radiance_with_refraction(shade, *through, bounces_left - 1, beyond,
                                                   schlick, offset);
    }
    return colour;
}

}  // namespace raystep
