#include "app/trace/trace_printer.h"

#include <cstddef>
#include <optional>

#include <glm/geometric.hpp>

#include "base/math/to_text.h"
#include "renderer/instance.h"
#include "renderer/local_model.h"
#include "renderer/solids.h"
#include "renderer/surface_point.h"
#include "stages/3_intersect/intersect.h"
#include "stages/6_shading/shading.h"
#include "stages/7_recursion/recursion.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

namespace {

using Lines = std::vector<std::string>;

// Above this many primitives a trace lists only the ones hit and counts the misses: a mesh's
// 75,000 lines of "miss" would bury what the trace is for.
constexpr std::size_t kTraceEveryPrimitiveUpTo = 64;

std::string describe(const Hit& hit) {
    std::string text = "hit t=" + to_text(hit.t) + " normal " + to_text(hit.normal);
    if (hit.beta != 0.0 || hit.gamma != 0.0) {
        text += " beta=" + to_text(hit.beta) + " gamma=" + to_text(hit.gamma);
    }
    return text;
}

std::string describe(const Ray& ray) {
    return "origin " + to_text(ray.origin) + " direction " + to_text(ray.direction) + " t in [" +
           to_text(ray.t_min) + ", " + to_text(ray.t_max) + "]";
}

std::string describe_direction(const Ray& ray) {
    return "origin " + to_text(ray.origin) + " direction " + to_text(ray.direction);
}

// -- The eye ray's tests, primitive by primitive --

// Each primitive of one kind, tested on its own with the stage-3 function closest_hit uses;
// `scene_index` maps a list position to the primitive's place in the scene.
template <class Shape, class Intersect, class SceneIndex>
void trace_each(const RenderScene& render_scene, const Ray& ray, PrimitiveKind kind,
                const std::vector<Shape>& shapes, Intersect intersect, SceneIndex scene_index,
                Lines& lines) {
    const bool list_all = shapes.size() <= kTraceEveryPrimitiveUpTo;
    std::size_t misses = 0;
    for (std::size_t k = 0; k < shapes.size(); ++k) {
        const std::optional<Hit> hit = intersect(ray, shapes[k]);
        if (!hit) ++misses;
        if (hit || list_all) {
            const std::size_t index = scene_index(k);
            lines.push_back(std::string(kind_name(kind)) + " " + std::to_string(index) + " (line " +
                            std::to_string(attributes_of(render_scene, kind, index).line) +
                            "): " + (hit ? describe(*hit) : "miss"));
        }
    }
    if (!list_all && misses > 0) {
        lines.push_back(std::to_string(misses) + " other " + kind_name(kind) + "s: miss");
    }
}

// What an instance holds: "sphere 3 (line 12)" for a transformed sphere alone, else its counts
// and the line of its first member.
std::string instance_label(const RenderScene& render_scene, std::size_t k) {
    const Scene& scene = *render_scene.scene;
    if (k >= render_scene.first_mesh_instance) {
        const MeshInstance& mesh = scene.mesh_instances[k - render_scene.first_mesh_instance];
        return "mesh instance of '" + scene.mesh_definitions[mesh.definition].name + "' (line " +
               std::to_string(mesh.attributes.line) + ")";
    }
    const InstanceGeometry& geometry =
        render_scene.instance_geometries[render_scene.instances[k].geometry];
    const PrimitiveKind kind =
        geometry.sphere_ids.empty() ? PrimitiveKind::triangle : PrimitiveKind::sphere;
    const std::size_t first =
        geometry.sphere_ids.empty() ? geometry.triangle_ids[0] : geometry.sphere_ids[0];
    const std::size_t count = geometry.sphere_ids.size() + geometry.triangle_ids.size();
    const std::string line =
        "line " + std::to_string(attributes_of(render_scene, kind, first).line);
    if (count == 1)
        return std::string(kind_name(kind)) + " " + std::to_string(first) + " (" + line + ")";
    return std::to_string(count) + " primitives under one transform (the first at " + line + ")";
}

// Each instance, with the ray in its own frame: where stage 5 goes wrong, the object-frame ray
// shows it.
void trace_instances(const RenderScene& render_scene, const Ray& ray, Lines& lines) {
    const std::vector<Instance>& instances = render_scene.instances;
    const bool list_all = instances.size() <= kTraceEveryPrimitiveUpTo;
    std::size_t misses = 0;
    for (std::size_t k = 0; k < instances.size(); ++k) {
        const Instance& instance = instances[k];
        const std::optional<PrimitiveHit> hit = instance_closest_hit(
            instance, render_scene.instance_geometries[instance.geometry], ray, nullptr);
        if (!hit) ++misses;
        if (!hit && !list_all) continue;
        std::string text = instance_label(render_scene, k);
        if (instance.transform) {
            const Ray object = ray_to_object(*instance.transform, ray);
            text += ", under a transform: object-frame ray origin " + to_text(object.origin) +
                    " direction " + to_text(object.direction);
        }
        text += ": ";
        if (hit) {
            // The primitive's own line: an instance may hold many
            text += std::string(kind_name(hit->kind)) + " " + std::to_string(hit->index) +
                    " (line " +
                    std::to_string(attributes_of(render_scene, hit->kind, hit->index).line) + ") " +
                    describe(hit->hit);
        } else {
            text += "miss";
        }
        lines.push_back(text);
    }
    if (!list_all && misses > 0) {
        lines.push_back(std::to_string(misses) + " other instances: miss");
    }
}

// -- Shading --

const char* light_kind_name(LightKind kind) {
    switch (kind) {
        case LightKind::point:
            return "point";
        case LightKind::directional:
            return "directional";
        case LightKind::spot:
            return "spot";
    }
    return "unknown";
}

// What blocks a shadow ray: the nearest blocker, though the render only asks whether there is
// one.
std::string blocker(const RenderScene& render_scene, const Ray& shadow) {
    const std::optional<PrimitiveHit> hit = scene_closest_hit(render_scene, shadow, nullptr);
    if (!hit) return "reaches the light";
    return "blocked by " + std::string(kind_name(hit->kind)) + " " + std::to_string(hit->index) +
           " (line " + std::to_string(attributes_of(render_scene, hit->kind, hit->index).line) +
           ") at t=" + to_text(hit->hit.t);
}

// The diffuse and specular parts of one light's term, each from the dialect's light_term with the
// other colour zeroed: the trace shows which one a wrong pixel gets wrong.
std::string light_terms(SceneDialect dialect, const Material& material, const SurfacePoint& point,
                        const LightSample& light, const std::string& name) {
    Material diffuse_only = material;
    diffuse_only.specular = Color(0.0);
    Material specular_only = material;
    specular_only.diffuse = Color(0.0);
    return "  " + name + " diffuse " + to_text(light_term(dialect, diffuse_only, point, light)) +
           " specular " + to_text(light_term(dialect, specular_only, point, light));
}

// -- Refraction --

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

// The path through transmitting surfaces: from the eye, at each surface that transmits, the
// media on both sides, F and the refracted ray from stage 9's functions, then on along the
// refracted ray (the reflected one under total internal reflection) while bounces remain. The
// colour comes from radiance_with_refraction, which follows every branch; a trace follows one.
void trace_transmission_path(const RenderScene& render_scene, const Ray& eye_ray, Lines& lines) {
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
        lines.push_back(
            "transmission " + std::to_string(bounce + 1) + ": " + (in ? "entering" : "leaving") +
            " solid " + std::to_string(solid.solid) + " (" + kind_name(hit->kind) + " " +
            std::to_string(hit->index) + "), media " + std::to_string(inside.size()) + " -> " +
            std::to_string(beyond.size()) + ", n1=" + to_text(n1) + " n2=" + to_text(n2) +
            " cos=" + to_text(cosine) + (scene.schlick_fresnel ? " Schlick" : " exact") +
            " F=" + to_text(through ? fresnel : 1.0) + " Kt " + to_text(material.transmission));
        if (through) {
            lines.push_back("  refracted ray " + describe_direction(*through));
            ray = *through;
            inside = beyond;
        } else {
            ray = reflected_ray(point, render_scene.ray_offset);
            lines.push_back("  total internal reflection: reflected ray " +
                            describe_direction(ray));
        }
    }
}

}  // namespace

std::string light_name(const char* kind, std::uint32_t line) {
    return std::string(kind) + " light (line " + std::to_string(line) + ")";
}

// A sampled pixel: every step of its first sample, then each sample's film point and colour,
// then the mean.
bool TracePrinter::sample_starts(int index, const Vec2& film_point) {
    add("camera sample " + std::to_string(index) + " through film point (" + to_text(film_point.x) +
        ", " + to_text(film_point.y) + ")" + (index == 0 ? ", every step:" : ""));
    return index == 0;
}

void TracePrinter::sample_ends(int index, const Color& colour) {
    if (index != 0) add("  colour " + to_text(colour));
}

void TracePrinter::pixel_mean(int samples, const Color& colour) {
    add("pixel colour: the mean of " + std::to_string(samples) + " samples, " + to_text(colour));
}

void TracePrinter::camera_ray(const Ray& ray) {
    add("camera ray: " + describe(ray));
}

void TracePrinter::hit_search_starts(const Ray& ray) {
    const PrimitiveList& list = render_scene_.primitives;
    trace_each(
        render_scene_, ray, PrimitiveKind::sphere, list.spheres, intersect_sphere,
        [&](std::size_t k) { return render_scene_.sphere_index[k]; }, lines_);
    trace_each(
        render_scene_, ray, PrimitiveKind::triangle, list.triangles, intersect_triangle,
        [&](std::size_t k) { return render_scene_.triangle_index[k]; }, lines_);
    trace_each(
        render_scene_, ray, PrimitiveKind::plane, list.planes, intersect_plane,
        [](std::size_t k) { return k; }, lines_);
    trace_instances(render_scene_, ray, lines_);
}

void TracePrinter::closest_hit(const Ray& ray, const std::optional<PrimitiveHit>& hit,
                               const TraversalStats& cost) {
    if (render_scene_.bvh || render_scene_.instance_bvh) {
        add("BVH: " + std::to_string(cost.nodes) + " nodes visited, " +
            std::to_string(cost.primitive_tests) + " primitives tested");
    }
    if (!hit) {
        add("closest_hit: miss");
        return;
    }
    add("closest_hit: " + std::string(kind_name(hit->kind)) + " " + std::to_string(hit->index) +
        " at t=" + to_text(hit->hit.t) + " point " + to_text(ray.at(hit->hit.t)) + " normal " +
        to_text(hit->hit.normal));
}

void TracePrinter::surface(const SurfacePoint& point, const Material& material) {
    point_ = point;
    material_ = material;
    reaching_.clear();
    add("surface point " + to_text(point.position) + " error " + to_text(point.error) + " normal " +
        to_text(point.normal) + " shading normal " + to_text(point.shading_normal));
}

void TracePrinter::light(const LightStep& step) {
    const std::string name = light_name(light_kind_name(step.kind), step.line);
    if (step.reach == LightReach::behind) {
        add(name + ": behind the surface, no shadow ray");
        return;
    }
    add(name + ": direction " + to_text(step.sample.direction) + " distance " +
        to_text(step.sample.distance) + " intensity " + to_text(step.sample.intensity));
    add("  shadow ray " + describe(*step.shadow_ray) + ": " +
        blocker(render_scene_, *step.shadow_ray));
    if (step.reach == LightReach::reaches) reaching_.push_back(name);
}

void TracePrinter::quad_light_seen(const SeenQuadLight& seen) {
    add(light_name("quad", seen.light->line) + " seen at t " + to_text(seen.t) +
        ", nearer than any surface (the CSE168 dialect draws quad lights): " +
        (seen.colour == Color(0.0) ? "its back, black" : "its radiance " + to_text(seen.colour)));
}

void TracePrinter::spot_light_outside_cone(std::uint32_t line) {
    add(light_name("spot", line) + ": no light here, outside its cone");
}

void TracePrinter::quad_light_starts(const QuadLight& light) {
    const Scene& scene = *render_scene_.scene;
    if (scene.integrator == Integrator::analyticdirect) {
        add(light_name("quad", light.line) +
            ": integrated exactly by Lambert's formula, unshadowed (integrator analyticdirect)");
        return;
    }
    add(light_name("quad", light.line) + ": " + std::to_string(scene.light_samples) + " samples, " +
        (scene.light_stratify ? "jittered" : "random"));
}

void TracePrinter::quad_light_sample(int index, const Ray& shadow_ray, bool /*blocked*/) {
    add("  light sample " + std::to_string(index) + ": shadow ray " + describe(shadow_ray) + ": " +
        blocker(render_scene_, shadow_ray));
}

void TracePrinter::quad_light_ends(const QuadLight& light, const Color& term, int shadow_rays) {
    add("  " + light_name("quad", light.line) + " term " + to_text(term) + " (" +
        std::to_string(shadow_rays) + " shadow rays; samples behind the surface send none)");
}

void TracePrinter::local_colour(const std::vector<LightSample>& reaching, const Color& colour) {
    add("shading: ambient " + to_text(material_->ambient) + " emission " +
        to_text(material_->emission));
    for (std::size_t k = 0; k < reaching.size(); ++k)
        add(light_terms(render_scene_.scene->dialect, *material_, point_, reaching[k],
                        reaching_[k]));
    add("local colour " + to_text(colour));
}

void TracePrinter::later_ray(int index, const Ray& ray, const std::optional<PrimitiveHit>& hit) {
    add(std::string(render_scene_.refraction ? "secondary ray " : "reflected ray ") +
        std::to_string(index) + ": " + describe_direction(ray) +
        describe_landing(render_scene_, hit));
}

void TracePrinter::path_ray(int index, const Ray& ray, const std::optional<PrimitiveHit>& hit,
                            const SeenQuadLight* light) {
    std::string text = "path ray " + std::to_string(index) +
                       (index == 0 ? " (the eye ray): " : ": ") + describe_direction(ray);
    if (light) {
        text += " meets " + light_name("quad", light->light->line) + " at t=" + to_text(light->t) +
                (light->colour == Color(0.0) ? ", its back: black"
                                             : ", radiance " + to_text(light->colour));
    } else if (hit) {
        text += " hits " + std::string(kind_name(hit->kind)) + " " + std::to_string(hit->index) +
                " (line " +
                std::to_string(attributes_of(render_scene_, hit->kind, hit->index).line) +
                ") at t=" + to_text(hit->hit.t);
    } else {
        text += " leaves the scene: black";
    }
    add(text);
}

void TracePrinter::path_shadow_ray(const Ray& ray, bool /*blocked*/) {
    add("  shadow ray " + describe(ray) + ": " + blocker(render_scene_, ray));
}

void TracePrinter::recursion_colour(const Ray& eye_ray, const Color& colour) {
    if (render_scene_.refraction) trace_transmission_path(render_scene_, eye_ray, lines_);
    add("colour " + to_text(colour));
}

}  // namespace raystep
