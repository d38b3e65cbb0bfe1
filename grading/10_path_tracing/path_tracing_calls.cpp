// Stage 10's batched calls, and the scene path_radiance meets in the probe: an enclosing sphere, a
// floor and quad lights, intersected here in double by the probe's own code, so that a path's
// mean depends only on the student's path and what it calls of the stage.

#include "grading/10_path_tracing/path_tracing_calls.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace raystep::probe {

namespace {

Vec3 direction_by(const SamplerSetting& s, const Vec2& u, double choice) {
    switch (s.sampler) {
        case Sampler::uniform_hemisphere:
            return uniform_hemisphere(u);
        case Sampler::cosine_hemisphere:
            return cosine_hemisphere(u);
        case Sampler::phong_lobe:
            return phong_lobe(u, s.parameter);
        case Sampler::ggx_half_vector:
            return ggx_half_vector(u, s.parameter);
        case Sampler::brdf:
            return sample_brdf(s.brdf, s.normal, s.to_eye, u, choice);
    }
    throw std::invalid_argument("unknown sampler");
}

double density_by(const SamplerSetting& s, const Vec3& direction) {
    switch (s.sampler) {
        case Sampler::uniform_hemisphere:
            return uniform_hemisphere_pdf(direction);
        case Sampler::cosine_hemisphere:
            return cosine_hemisphere_pdf(direction);
        case Sampler::phong_lobe:
            return phong_lobe_pdf(direction, s.parameter);
        case Sampler::ggx_half_vector:
            return ggx_half_vector_pdf(direction, s.parameter);
        case Sampler::brdf:
            return brdf_pdf(s.brdf, s.normal, s.to_eye, direction);
    }
    throw std::invalid_argument("unknown sampler");
}

SurfacePoint facing_point(const Vec3& position, const Vec3& normal, const Ray& ray) {
    const Vec3 facing = glm::dot(normal, ray.direction) > 0.0 ? -normal : normal;
    return {position, Vec3(0.0), facing, facing, -glm::normalize(ray.direction)};
}

// The nearest of the enclosure's, the floor's and the lights' hits within the ray's range, and
// its distance; whether only blockers count (a shadow ray) is `blockers_only`.
struct NearestHit {
    double t = 0.0;
    std::optional<PathHit> hit;
};

void consider(NearestHit& nearest, const Ray& ray, double t, PathHit hit) {
    if (!(t > ray.t_min && t < ray.t_max)) return;
    if (nearest.hit && !(t < nearest.t)) return;
    nearest.t = t;
    nearest.hit = std::move(hit);
}

NearestHit nearest_hit(const PathSceneQuestion& q, const Ray& ray, bool blockers_only) {
    NearestHit nearest;
    if (q.enclosure) {
        const Enclosure& e = *q.enclosure;
        const Vec3 o = ray.origin - e.centre;
        const double a = glm::dot(ray.direction, ray.direction);
        const double b = glm::dot(o, ray.direction);
        const double c = glm::dot(o, o) - e.radius * e.radius;
        const double discriminant = b * b - a * c;
        if (discriminant >= 0.0) {
            const double t = (-b + std::sqrt(discriminant)) / a;  // from inside: the far root
            const Vec3 position = ray.origin + t * ray.direction;
            PathHit hit;
            hit.point = facing_point(position, glm::normalize(position - e.centre), ray);
            hit.brdf = e.brdf;
            hit.emission = e.emission;
            consider(nearest, ray, t, hit);
        }
    }
    if (q.floor) {
        const double facing = glm::dot(q.floor->normal, ray.direction);
        if (facing != 0.0) {
            const double t = glm::dot(q.floor->normal, q.floor->point - ray.origin) / facing;
            PathHit hit;
            hit.point = facing_point(ray.origin + t * ray.direction, q.floor->normal, ray);
            hit.brdf = q.floor->brdf;
            consider(nearest, ray, t, hit);
        }
    }
    if (blockers_only) return nearest;
    for (std::size_t k = 0; k < q.lights.size(); ++k) {
        const QuadLight& light = q.lights[k];
        const Vec3 normal = glm::cross(light.edge1, light.edge2);
        const double facing = glm::dot(normal, ray.direction);
        if (facing == 0.0) continue;
        const double t = glm::dot(normal, light.corner - ray.origin) / facing;
        const Vec3 offset = ray.origin + t * ray.direction - light.corner;
        const double n2 = glm::dot(normal, normal);
        const double s = glm::dot(glm::cross(offset, light.edge2), normal) / n2;
        const double r = glm::dot(glm::cross(light.edge1, offset), normal) / n2;
        if (!(s >= 0.0 && s <= 1.0 && r >= 0.0 && r <= 1.0)) continue;
        PathHit hit;
        hit.point = facing_point(ray.origin + t * ray.direction, glm::normalize(normal), ray);
        // The emitting side is ac x ab, against ab x ac: lit where the ray runs along ab x ac.
        hit.emission = facing > 0.0 ? light.radiance : Color(0.0);
        hit.light = k;
        consider(nearest, ray, t, hit);
    }
    return nearest;
}

}  // namespace

std::vector<Vec3> directions_of(const DirectionsQuestion& q) {
    std::vector<Vec3> directions;
    directions.reserve(q.us.size());
    for (std::size_t k = 0; k < q.us.size(); ++k)
        directions.push_back(
            direction_by(q.setting, q.us[k], k < q.choices.size() ? q.choices[k] : 0.0));
    return directions;
}

std::vector<double> densities_of(const DensitiesQuestion& q) {
    std::vector<double> densities;
    densities.reserve(q.directions.size());
    for (const Vec3& direction : q.directions)
        densities.push_back(density_by(q.setting, direction));
    return densities;
}

std::vector<LightDirectionSample> light_directions_of(const LightDirectionsQuestion& q) {
    std::vector<LightDirectionSample> samples;
    samples.reserve(q.us.size());
    for (const Vec2& u : q.us)
        samples.push_back(sample_light_direction(q.light, q.point, u));
    return samples;
}

std::vector<std::optional<Color>> roulette_of(const RouletteQuestion& q) {
    std::vector<std::optional<Color>> weights;
    weights.reserve(q.us.size());
    for (const double u : q.us)
        weights.push_back(russian_roulette(q.throughput, u));
    return weights;
}

PathScene path_scene(const PathSceneQuestion& q) {
    PathScene scene;
    scene.intersect = [q](const Ray& ray) { return nearest_hit(q, ray, false).hit; };
    scene.occluded = [q](const Ray& ray) {
        return q.shadows_blocked || nearest_hit(q, ray, true).hit.has_value();
    };
    scene.lights = q.lights;
    scene.offset = q.offset;
    return scene;
}

std::vector<Color> paths_of(const PathsQuestion& q) {
    const PathScene scene = path_scene(q.scene);
    std::vector<Color> colours;
    colours.reserve(static_cast<std::size_t>(std::max(q.count, 0)));
    for (int k = 0; k < q.count; ++k) {
        RandomStream random(q.seed, q.first_stream + static_cast<std::uint64_t>(k));
        colours.push_back(path_radiance(q.ray, scene, q.settings, random));
    }
    return colours;
}

}  // namespace raystep::probe
