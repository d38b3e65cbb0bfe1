#include "app/render/render_pixel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "app/render/heat_map.h"
#include "app/render/ray_colour.h"
#include "app/render/sample_streams.h"
#include "app/render/shade_hit.h"
#include "base/math/to_text.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

namespace {

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

// Each primitive of one kind, tested on its own with the stage-3 function closest_hit uses;
// `scene_index` maps a list position to the primitive's place in the scene.
template <class Shape, class Intersect, class SceneIndex>
void trace_each(const RenderScene& render_scene, const Ray& ray, PrimitiveKind kind,
                const std::vector<Shape>& shapes, Intersect intersect, SceneIndex scene_index,
                TraceLog& trace) {
    const bool list_all = shapes.size() <= kTraceEveryPrimitiveUpTo;
    std::size_t misses = 0;
    for (std::size_t k = 0; k < shapes.size(); ++k) {
        const std::optional<Hit> hit = intersect(ray, shapes[k]);
        if (!hit) ++misses;
        if (hit || list_all) {
            const std::size_t index = scene_index(k);
            trace.add(std::string(kind_name(kind)) + " " + std::to_string(index) + " (line " +
                      std::to_string(attributes_of(render_scene, kind, index).line) +
                      "): " + (hit ? describe(*hit) : "miss"));
        }
    }
    if (!list_all && misses > 0) {
        trace.add(std::to_string(misses) + " other " + kind_name(kind) + "s: miss");
    }
}

// What an instance holds, for a trace: "sphere 3 (line 12)" for a transformed sphere alone,
// else its counts and the line of its first member.
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
void trace_instances(const RenderScene& render_scene, const Ray& ray, TraceLog& trace) {
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
        trace.add(text);
    }
    if (!list_all && misses > 0) {
        trace.add(std::to_string(misses) + " other instances: miss");
    }
}

void trace_primitives(const RenderScene& render_scene, const Ray& ray, TraceLog& trace) {
    const PrimitiveList& list = render_scene.primitives;
    trace_each(
        render_scene, ray, PrimitiveKind::sphere, list.spheres, intersect_sphere,
        [&](std::size_t k) { return render_scene.sphere_index[k]; }, trace);
    trace_each(
        render_scene, ray, PrimitiveKind::triangle, list.triangles, intersect_triangle,
        [&](std::size_t k) { return render_scene.triangle_index[k]; }, trace);
    trace_each(
        render_scene, ray, PrimitiveKind::plane, list.planes, intersect_plane,
        [](std::size_t k) { return k; }, trace);
    trace_instances(render_scene, ray, trace);
}

Color direction_color(const Vec3& direction) {
    return 0.5 * (direction + Vec3(1.0));
}

// Everything after the camera ray, for one ray: its closest hit and what the view makes of it.
// Quad lights draw from `light_random`.
Color camera_ray_colour(const RenderScene& render_scene, View view, const Ray& ray,
                        RandomStream* light_random, TraceLog* trace, PixelRecord* record) {
    if (record) record->camera_ray = ray;
    if (trace) {
        trace->add("camera ray: origin " + to_text(ray.origin) + " direction " +
                   to_text(ray.direction) + " t in [" + to_text(ray.t_min) + ", " +
                   to_text(ray.t_max) + "]");
    }
    if (view == View::rays) return direction_color(ray.direction);

    // Stages 3 and 4: the closest hit, through the BVH when the scene has one
    if (trace) trace_primitives(render_scene, ray, *trace);
    TraversalStats cost;
    const std::optional<PrimitiveHit> closest = scene_closest_hit(render_scene, ray, &cost);
    if (record) {
        record->hit_searched = true;
        record->hit = closest;
    }
    if (trace) {
        if (render_scene.bvh || render_scene.instance_bvh) {
            trace->add("BVH: " + std::to_string(cost.nodes) + " nodes visited, " +
                       std::to_string(cost.primitive_tests) + " primitives tested");
        }
        if (closest) {
            trace->add("closest_hit: " + std::string(kind_name(closest->kind)) + " " +
                       std::to_string(closest->index) + " at t=" + to_text(closest->hit.t) +
                       " point " + to_text(ray.at(closest->hit.t)) + " normal " +
                       to_text(closest->hit.normal));
        } else {
            trace->add("closest_hit: miss");
        }
    }

    switch (view) {
        case View::depth:
            return Color(closest ? closest->hit.t : std::numeric_limits<double>::infinity());
        case View::normal:
            return closest ? direction_color(closest->hit.normal) : Color(0.0);
        case View::cost:
            return Color(static_cast<double>(cost.nodes + cost.primitive_tests));
        case View::barycentric:
            if (!closest) return Color(0.0);
            if (closest->kind != PrimitiveKind::triangle) return Color(0.25);
            return {1.0 - closest->hit.beta - closest->hit.gamma, closest->hit.beta,
                    closest->hit.gamma};
        case View::shaded:
            if (!closest) return render_scene.scene->background;
            return shade_hit(render_scene, ray, *closest, light_random, trace, record).local;
        case View::full: {
            // Without bounces there is nothing to follow: the local colour, with no recursion
            // to set up (most scenes of stages 2 to 6 take this way on every pixel).
            Color colour = render_scene.scene->background;
            if (render_scene.bounces > 0) {
                colour = full_colour(render_scene, ray, closest, light_random, trace, record);
            } else if (closest) {
                colour = shade_hit(render_scene, ray, *closest, light_random, trace, record).local;
            }
            if (record) record->full = colour;
            return colour;
        }
        case View::rays:
            break;
    }
    return Color(0.0);
}

// Stage 8's antialiasing: the mean over the pixel's samples, each a camera ray through its own
// film point with its own stream of light samples (sample_streams.h). A trace shows every step
// of the first sample, then each sample's film point and colour, then the mean.
Color sampled_pixel(const RenderScene& render_scene, View view, int i, int j, TraceLog* trace,
                    PixelRecord* record) {
    const Scene& scene = *render_scene.scene;
    // The record is the pixel's centre ray's, as at one sample per pixel: the samples may come
    // in any order (stage 8's contract), and the centre ray's steps do not depend on it, so a
    // student's record can be held against the reference's.
    if (record) {
        RandomStream lights = light_random(scene, i, j, 0);
        camera_ray_colour(render_scene, view, camera_ray(render_scene, i, j), &lights, nullptr,
                          record);
    }
    RandomStream film = film_random(scene, i, j);
    int sample = 0;
    const FilmRadiance radiance = [&](const Vec2& film_point) {
        const bool first = sample == 0;
        if (trace) {
            trace->add("camera sample " + std::to_string(sample) + " through film point (" +
                       to_text(film_point.x) + ", " + to_text(film_point.y) + ")" +
                       (first ? ", every step:" : ""));
        }
        RandomStream lights = light_random(scene, i, j, sample);
        const Color colour =
            camera_ray_colour(render_scene, view, camera_ray_through(render_scene, film_point),
                              &lights, first ? trace : nullptr, nullptr);
        if (trace && !first) trace->add("  colour " + to_text(colour));
        ++sample;
        return colour;
    };
    const Color colour =
        pixel_colour(radiance, i, j, scene.pixel_sampling, scene.samples_per_pixel, film);
    if (trace) {
        trace->add("pixel colour: the mean of " + std::to_string(scene.samples_per_pixel) +
                   " samples, " + to_text(colour));
    }
    return colour;
}

}  // namespace

Color render_pixel(const RenderScene& render_scene, View view, int i, int j, TraceLog* trace,
                   PixelRecord* record) {
    const Scene& scene = *render_scene.scene;
    if (averages_samples(view) && scene.samples_per_pixel > 1) {
        return sampled_pixel(render_scene, view, i, j, trace, record);
    }
    // One ray through the pixel's centre, stage 2's: a scene without samples needs nothing of
    // stage 8, and the light samples of a quad light at spp 1 use sample 0's stream.
    std::optional<RandomStream> lights;
    if (!scene.quad_lights.empty() && averages_samples(view)) {
        lights.emplace(light_random(scene, i, j, 0));
    }
    return camera_ray_colour(render_scene, view, camera_ray(render_scene, i, j),
                             lights ? &*lights : nullptr, trace, record);
}

namespace {

// Inverse depth: the nearest positive t in the image is white, twice as far 0.5.
void finish_depth(Image& image) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            const double t = image.at(i, j).r;
            if (t > 0.0) nearest = std::min(nearest, t);
        }
    }
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            const double t = image.at(i, j).r;
            // t = 0 (a hit on the eye plane of an orthographic camera) is as near as it gets.
            const double grey = !std::isfinite(t) ? 0.0 : (t > 0.0 ? nearest / t : 1.0);
            image.set(i, j, Color(grey));
        }
    }
}

void finish_cost(Image& image) {
    double most = 0.0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i)
            most = std::max(most, image.at(i, j).r);
    }
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            image.set(i, j, heat_colour(most > 0.0 ? image.at(i, j).r / most : 0.0));
        }
    }
}

}  // namespace

void finish_view(Image& image, View view) {
    if (view == View::depth) finish_depth(image);
    if (view == View::cost) finish_cost(image);
}

}  // namespace raystep
