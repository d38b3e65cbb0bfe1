#include "app/render/ray_colour.h"

#include <string>

#include <glm/geometric.hpp>

#include "app/render/shade_hit.h"
#include "app/render/solids.h"
#include "app/render/surface_point.h"
#include "base/math/to_text.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

namespace {

std::string describe_ray(const Ray& ray) {
    return "origin " + to_text(ray.origin) + " direction " + to_text(ray.direction);
}

std::string describe_landing(const RenderScene& render_scene,
                             const std::optional<PrimitiveHit>& hit) {
    if (!hit) {
        return render_scene.scene->background == Color(0.0)
                   ? " leaves the scene"
                   : " leaves the scene: background " + to_text(render_scene.scene->background);
    }
    return " hits " + std::string(kind_name(hit->kind)) + " " + std::to_string(hit->index) +
           " at t=" + to_text(hit->hit.t);
}

// The material of a hit primitive.
const Material& material_of(const RenderScene& render_scene, const PrimitiveHit& hit) {
    return render_scene.scene->materials[attributes_of(render_scene, hit.kind, hit.index).material];
}

// Stage 9's view of a surface: the solid it bounds, with the material's index, and whether the
// ray arrives from outside, against the outward normal (a sphere's outward normal, a triangle's
// winding normal: the hit's normal before surface_point turns it towards the ray).
Medium medium_of(const RenderScene& render_scene, const PrimitiveHit& hit) {
    return {solid_of(render_scene, hit.kind, hit.index), material_of(render_scene, hit).index};
}

bool entering(const Ray& ray, const PrimitiveHit& hit) {
    return glm::dot(ray.direction, hit.hit.normal) < 0.0;
}

// The path a trace follows through transmitting surfaces: from the eye, at each surface that
// transmits, the media on both sides, F and the refracted ray from stage 9's functions, then on
// along the refracted ray (the reflected one under total internal reflection) while bounces
// remain. Only for a trace: the colour comes from radiance_with_refraction, which follows every
// branch.
void trace_transmission_path(const RenderScene& render_scene, const Ray& eye_ray, TraceLog& trace) {
    const Scene& scene = *render_scene.scene;
    Ray ray = eye_ray;
    MediumStack inside;
    for (int bounce = 0; bounce < render_scene.bounces; ++bounce) {
        const std::optional<PrimitiveHit> hit = scene_closest_hit(render_scene, ray, nullptr);
        if (!hit) return;
        const Material& material = material_of(render_scene, *hit);
        if (material.transmission == Color(0.0)) return;
        const SurfacePoint point = surface_point(render_scene, ray, *hit);
        const Medium solid = medium_of(render_scene, *hit);
        const bool in = entering(ray, *hit);
        const MediumStack beyond = after_crossing(inside, solid, in);
        const double n1 = current_index(inside);
        const double n2 = current_index(beyond);
        const double cosine = glm::dot(point.to_eye, point.shading_normal);
        const double fresnel =
            scene.schlick_fresnel ? fresnel_schlick(cosine, n1, n2) : fresnel_exact(cosine, n1, n2);
        const std::optional<Ray> through = refracted_ray(point, n1, n2, render_scene.ray_offset);
        trace.add(
            "transmission " + std::to_string(bounce + 1) + ": " + (in ? "entering" : "leaving") +
            " solid " + std::to_string(solid.solid) + " (" + kind_name(hit->kind) + " " +
            std::to_string(hit->index) + "), media " + std::to_string(inside.size()) + " -> " +
            std::to_string(beyond.size()) + ", n1=" + to_text(n1) + " n2=" + to_text(n2) +
            " cos=" + to_text(cosine) + (scene.schlick_fresnel ? " Schlick" : " exact") +
            " F=" + to_text(through ? fresnel : 1.0) + " Kt " + to_text(material.transmission));
        if (through) {
            trace.add("  refracted ray " + describe_ray(*through));
            ray = *through;
            inside = beyond;
        } else {
            ray = reflected_ray(point, render_scene.ray_offset);
            trace.add("  total internal reflection: reflected ray " + describe_ray(ray));
        }
    }
}

}  // namespace

std::optional<ShadedHit> background_hit(const Ray& ray, const Color& background) {
    if (background == Color(0.0)) return std::nullopt;
    const Vec3 back = -glm::normalize(ray.direction);
    SurfacePoint point{ray.origin, Vec3(0.0), back, back, back};
    return ShadedHit{point, background, Color(0.0)};
}

Color full_colour(const RenderScene& render_scene, const Ray& eye_ray,
                  const std::optional<PrimitiveHit>& eye_hit, RandomStream* light_random,
                  TraceLog* trace, PixelRecord* record) {
    const Scene& scene = *render_scene.scene;
    // The eye ray's hit is already known; every later ray is found and shaded here. A later ray
    // of stage 9 may be reflected or refracted: the shade function sees only the ray.
    int rays = 0;
    const auto find = [&](const Ray& ray) {
        if (rays++ == 0) return eye_hit;
        const std::optional<PrimitiveHit> hit = scene_closest_hit(render_scene, ray, nullptr);
        if (trace) {
            trace->add(std::string(render_scene.refraction ? "secondary ray " : "reflected ray ") +
                       std::to_string(rays - 1) + ": " + describe_ray(ray) +
                       describe_landing(render_scene, hit));
        }
        return hit;
    };
    const auto shade = [&](const Ray& ray, const PrimitiveHit& hit) {
        return shade_hit(render_scene, ray, hit, light_random, trace, rays == 1 ? record : nullptr);
    };

    Color colour;
    if (render_scene.refraction) {
        const MediumShadeFunction shade_medium = [&](const Ray& ray) -> std::optional<MediumHit> {
            const std::optional<PrimitiveHit> hit = find(ray);
            if (!hit) {
                const std::optional<ShadedHit> sky = background_hit(ray, scene.background);
                if (!sky) return std::nullopt;
                return MediumHit{*sky, Color(0.0), Medium{0, 1.0}, false};
            }
            return MediumHit{shade(ray, *hit), material_of(render_scene, *hit).transmission,
                             medium_of(render_scene, *hit), entering(ray, *hit)};
        };
        colour = radiance_with_refraction(shade_medium, eye_ray, render_scene.bounces, {},
                                          scene.schlick_fresnel, render_scene.ray_offset);
        if (trace) trace_transmission_path(render_scene, eye_ray, *trace);
    } else {
        const ShadeFunction shade_mirror = [&](const Ray& ray) -> std::optional<ShadedHit> {
            const std::optional<PrimitiveHit> hit = find(ray);
            if (!hit) return background_hit(ray, scene.background);
            return shade(ray, *hit);
        };
        colour = radiance(shade_mirror, eye_ray, render_scene.bounces, render_scene.ray_offset);
    }
    if (trace) trace->add("colour " + to_text(colour));
    return colour;
}

}  // namespace raystep
