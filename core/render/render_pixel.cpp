#include "core/render/render_pixel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/math/to_text.h"

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

// Each primitive of one kind, tested on its own with the stage-3 function closest_hit uses.
template <class Shape, class Intersect>
void trace_each(const RenderScene& render_scene, const Ray& ray, PrimitiveKind kind,
                const std::vector<Shape>& shapes, Intersect intersect, TraceLog& trace) {
    const bool list_all = shapes.size() <= kTraceEveryPrimitiveUpTo;
    std::size_t misses = 0;
    for (std::size_t k = 0; k < shapes.size(); ++k) {
        const std::optional<Hit> hit = intersect(ray, shapes[k]);
        if (!hit) ++misses;
        if (hit || list_all) {
            trace.add(std::string(kind_name(kind)) + " " + std::to_string(k) + " (line " +
                      std::to_string(attributes_of(render_scene, kind, k).line) +
                      "): " + (hit ? describe(*hit) : "miss"));
        }
    }
    if (!list_all && misses > 0) {
        trace.add(std::to_string(misses) + " other " + kind_name(kind) + "s: miss");
    }
}

void trace_primitives(const RenderScene& render_scene, const Ray& ray, TraceLog& trace) {
    const PrimitiveList& list = render_scene.primitives;
    trace_each(render_scene, ray, PrimitiveKind::sphere, list.spheres, intersect_sphere, trace);
    trace_each(render_scene, ray, PrimitiveKind::triangle, list.triangles, intersect_triangle,
               trace);
    trace_each(render_scene, ray, PrimitiveKind::plane, list.planes, intersect_plane, trace);
}

Color direction_color(const Vec3& direction) {
    return 0.5 * (direction + Vec3(1.0));
}

}  // namespace

Color render_pixel(const RenderScene& render_scene, View view, int i, int j, TraceLog* trace) {
    // Stage 2: the camera ray
    const Ray ray = camera_ray(render_scene, i, j);
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
    if (trace) {
        if (render_scene.bvh) {
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
        case View::full:
            throw std::runtime_error(
                "the full image needs stage 6 (shading), not yet part of raystep; choose "
                "--view rays, depth, normal, barycentric or cost");
        case View::rays:
            break;
    }
    return Color(0.0);
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

// A heat map of the work per pixel, from black (none) through blue, red and yellow to white (the
// image's most expensive pixel): stops spread so that equal steps of work are visible steps.
Color heat(double fraction) {
    static const Color kStops[] = {
        {0, 0, 0}, {0.1, 0.1, 0.8}, {0.9, 0.1, 0.1}, {1, 0.9, 0}, {1, 1, 1}};
    const double x = std::clamp(fraction, 0.0, 1.0) * 4.0;
    const int k = std::min(3, static_cast<int>(x));
    return kStops[k] + (x - k) * (kStops[k + 1] - kStops[k]);
}

void finish_cost(Image& image) {
    double most = 0.0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i)
            most = std::max(most, image.at(i, j).r);
    }
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            image.set(i, j, heat(most > 0.0 ? image.at(i, j).r / most : 0.0));
        }
    }
}

}  // namespace

void finish_view(Image& image, View view) {
    if (view == View::depth) finish_depth(image);
    if (view == View::cost) finish_cost(image);
}

}  // namespace raystep
