// Stage 10 reference solution: a path, extended hit by hit.

#include <limits>
#include <stdexcept>

#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

namespace {

// The density with which `sampling` draws wi at the hit.
double direction_pdf(const PathSettings& settings, const PathHit& hit, const Vec3& to_light) {
    const Vec3& normal = hit.point.shading_normal;
    switch (settings.sampling) {
        case DirectionSampling::hemisphere:
            return uniform_hemisphere_pdf(to_local(frame_around(normal), to_light));
        case DirectionSampling::cosine:
            return cosine_hemisphere_pdf(to_local(frame_around(normal), to_light));
        case DirectionSampling::brdf:
            return brdf_pdf(hit.brdf, normal, hit.point.to_eye, to_light);
    }
    return 0.0;
}

// Next event estimation: one sample of each light, shadow-tested, weighted against the density
// of drawing the same direction with `mis`.
Color sampled_lights(const PathScene& scene, const PathSettings& settings, const PathHit& hit,
                     RandomStream& random) {
    const Vec3& normal = hit.point.shading_normal;
    Color sum(0.0);
    for (const QuadLight& light : scene.lights) {
        const LightDirectionSample sample =
            sample_light_direction(light, hit.point.position, random.next2());
        const double cos_i = dot(normal, sample.direction);
        if (!(sample.pdf > 0.0) || sample.radiance == Color(0.0) || !(cos_i > 0.0)) continue;
        LightSample towards{sample.direction, sample.distance, Color(0.0)};
        if (scene.occluded(shadow_ray(hit.point, towards, scene.offset))) continue;
        const double weight =
            settings.next_event == NextEvent::mis
                ? power_heuristic(sample.pdf, direction_pdf(settings, hit, sample.direction))
                : 1.0;
        sum += weight * evaluate_brdf(hit.brdf, normal, sample.direction, hit.point.to_eye) *
               cos_i * sample.radiance / sample.pdf;
    }
    return sum;
}

// A direction drawn by `sampling` at the hit.
Vec3 draw_direction(const PathSettings& settings, const PathHit& hit, RandomStream& random) {
    const Vec3& normal = hit.point.shading_normal;
    switch (settings.sampling) {
        case DirectionSampling::hemisphere:
            return to_world(frame_around(normal), uniform_hemisphere(random.next2()));
        case DirectionSampling::cosine:
            return to_world(frame_around(normal), cosine_hemisphere(random.next2()));
        case DirectionSampling::brdf: {
            const Vec2 u = random.next2();
            return sample_brdf(hit.brdf, normal, hit.point.to_eye, u, random.next());
        }
    }
    return normal;
}

}  // namespace

Color path_radiance(const Ray& ray, const PathScene& scene, const PathSettings& settings,
                    RandomStream& random) {
    if (settings.max_depth < 0 && !settings.russian_roulette) {
        throw std::domain_error(
            "path_radiance: max_depth -1 (no limit) needs Russian roulette: without it a path "
            "in a closed scene never ends");
    }
    Color radiance(0.0);
    Color throughput(1.0);
    Ray next = ray;
    Vec3 last_position(0.0);
    double last_pdf = 0.0;
    for (int bounce = 0;; ++bounce) {
        const std::optional<PathHit> hit = scene.intersect(next);
        if (!hit) break;

        double emission_weight = 1.0;
        if (bounce > 0 && hit->light) {
            if (settings.next_event == NextEvent::on) emission_weight = 0.0;
            if (settings.next_event == NextEvent::mis) {
                emission_weight = power_heuristic(
                    last_pdf,
                    light_direction_pdf(scene.lights[*hit->light], last_position, next.direction));
            }
        }
        radiance += emission_weight * throughput * hit->emission;
        if (bounce == settings.max_depth) break;

        if (settings.next_event != NextEvent::off)
            radiance += throughput * sampled_lights(scene, settings, *hit, random);

        const Vec3 to_light = draw_direction(settings, *hit, random);
        const Vec3& normal = hit->point.shading_normal;
        const double cos_i = dot(normal, to_light);
        const double pdf = direction_pdf(settings, *hit, to_light);
        if (!(cos_i > 0.0) || !(pdf > 0.0)) break;
        throughput *= evaluate_brdf(hit->brdf, normal, to_light, hit->point.to_eye) * cos_i / pdf;
        if (settings.russian_roulette) {
            const std::optional<Color> kept = russian_roulette(throughput, random.next());
            if (!kept) break;
            throughput = *kept;
        }
        next =
            spawn_ray(hit->point, to_light, std::numeric_limits<double>::infinity(), scene.offset);
        last_position = hit->point.position;
        last_pdf = pdf;
    }
    return radiance;
}

}  // namespace raystep
