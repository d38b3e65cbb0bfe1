// Stage 9 reference solution: the refracted ray, and radiance through mirrors and glass.

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
    const ShadedHit& shaded = hit->shaded;
    Color result = shaded.local;
    if (bounces_left <= 0) return result;

    // F and the refracted ray only where something goes through.
    double fresnel = 0.0;
    std::optional<Ray> through;
    MediumStack beyond;
    if (hit->transmission != Color(0.0)) {
        beyond = after_crossing(inside, hit->solid, hit->entering);
        const double n1 = current_index(inside);
        const double n2 = current_index(beyond);
        const double cos1 = dot(shaded.point.to_eye, shaded.point.shading_normal);
        fresnel = schlick ? fresnel_schlick(cos1, n1, n2) : fresnel_exact(cos1, n1, n2);
        through = refracted_ray(shaded.point, n1, n2, offset);
        if (!through) fresnel = 1.0;  // total internal reflection: everything is reflected
    }

    const Color reflect_weight = shaded.reflectance + hit->transmission * fresnel;
    if (reflect_weight != Color(0.0)) {
        result +=
            reflect_weight * radiance_with_refraction(shade, reflected_ray(shaded.point, offset),
                                                      bounces_left - 1, inside, schlick, offset);
    }
    const Color refract_weight = hit->transmission * (1.0 - fresnel);
    if (through && refract_weight != Color(0.0)) {
        result += refract_weight * radiance_with_refraction(shade, *through, bounces_left - 1,
                                                            beyond, schlick, offset);
    }
    return result;
}

}  // namespace raystep
