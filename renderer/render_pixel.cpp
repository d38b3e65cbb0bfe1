#include "renderer/render_pixel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "renderer/heat_map.h"
#include "renderer/path_traced.h"
#include "renderer/ray_colour.h"
#include "renderer/sample_streams.h"
#include "renderer/seen_quad_light.h"
#include "renderer/shade_hit.h"
#include "renderer/surface_maps.h"
#include "renderer/surface_point.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

namespace {

Color direction_color(const Vec3& direction) {
    return 0.5 * (direction + Vec3(1.0));
}

// Everything after the camera ray, for one ray: its closest hit and what the view makes of it.
// Quad lights draw from `light_random`.
Color camera_ray_colour(const RenderScene& render_scene, View view, const Ray& ray,
                        RandomStream* light_random, PixelObserver& observer) {
    observer.camera_ray(ray);
    if (view == View::rays) return direction_color(ray.direction);

    // Stages 3 and 4: the closest hit, through the BVH when the scene has one
    observer.hit_search_starts(ray);
    TraversalStats cost;
    const std::optional<PrimitiveHit> closest = scene_closest_hit(render_scene, ray, &cost);
    observer.closest_hit(ray, closest, cost);

    // The CSE168 dialect draws its quad lights in the views of the finished colour
    // (seen_quad_light.h).
    if (view == View::shaded || view == View::full || view == View::indirect) {
        if (const std::optional<SeenQuadLight> seen =
                seen_quad_light(*render_scene.scene, ray, closest)) {
            observer.quad_light_seen(*seen);
            // A light seen directly reflects nothing: it has no indirect light.
            const Color colour = view == View::indirect ? Color(0.0) : seen->colour;
            if (view != View::shaded) observer.finished_colour(colour);
            return colour;
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
        case View::uv: {
            if (!closest) return Color(0.0);
            const Vec2 uv = surface_uv(render_scene, ray, *closest).uv;
            return {uv.x - std::floor(uv.x), uv.y - std::floor(uv.y), 0.0};
        }
        case View::tangent: {
            if (!closest) return Color(0.0);
            const std::optional<SurfaceDerivatives> derivatives =
                surface_uv(render_scene, ray, *closest).derivatives;
            if (!derivatives) return Color(0.0);
            const SurfacePoint point = surface_point(render_scene, ray, *closest);
            const std::optional<TangentFrame> frame =
                tangent_frame(*derivatives, point.shading_normal);
            return frame ? direction_color(frame->tangent) : Color(0.0);
        }
        case View::shaded:
            if (!closest) return render_scene.scene->background;
            return shade_hit(render_scene, ray, *closest, light_random, observer).local;
        case View::full: {
            // Without bounces there is nothing to follow: the local colour, with no recursion
            // to set up (most scenes of stages 2 to 6 take this way on every pixel).
            Color colour = render_scene.scene->background;
            if (render_scene.scene->integrator == Integrator::pathtracer) {
                colour = path_traced_colour(render_scene, ray, *light_random, observer);
            } else if (render_scene.bounces > 0) {
                colour = full_colour(render_scene, ray, closest, light_random, observer);
            } else if (closest) {
                colour = shade_hit(render_scene, ray, *closest, light_random, observer).local;
            }
            observer.finished_colour(colour);
            return colour;
        }
        case View::indirect: {
            const Color colour =
                render_scene.scene->integrator == Integrator::pathtracer
                    ? path_traced_indirect_colour(render_scene, ray, *light_random, observer)
                    : Color(0.0);
            observer.finished_colour(colour);
            return colour;
        }
        case View::rays:
            break;
    }
    return Color(0.0);
}

// Stage 8's antialiasing: the mean over the pixel's samples, each a camera ray through its own
// film point with its own stream of light samples (sample_streams.h).
Color sampled_pixel(const RenderScene& render_scene, View view, int i, int j,
                    PixelObserver& observer) {
    const Scene& scene = *render_scene.scene;
    if (observer.watches_centre_ray()) {
        RandomStream lights = light_random(scene, i, j, 0);
        camera_ray_colour(render_scene, view, camera_ray(render_scene, i, j), &lights, observer);
    }
    RandomStream film = film_random(scene, i, j);
    int sample = 0;
    const FilmRadiance radiance = [&](const Vec2& film_point) {
        const bool watched = observer.sample_starts(sample, film_point);
        RandomStream lights = light_random(scene, i, j, sample);
        const Color colour =
            camera_ray_colour(render_scene, view, camera_ray_through(render_scene, film_point),
                              &lights, watched ? observer : unobserved());
        observer.sample_ends(sample, colour);
        ++sample;
        return colour;
    };
    const Color colour =
        pixel_colour(radiance, i, j, scene.pixel_sampling, scene.samples_per_pixel, film);
    observer.pixel_mean(scene.samples_per_pixel, colour);
    return colour;
}

}  // namespace

Color render_pixel(const RenderScene& render_scene, View view, int i, int j,
                   PixelObserver& observer) {
    const Scene& scene = *render_scene.scene;
    if (averages_samples(view) && scene.samples_per_pixel > 1) {
        return sampled_pixel(render_scene, view, i, j, observer);
    }
    // One ray through the pixel's centre, stage 2's: a scene without samples needs nothing of
    // stage 8, and the light samples of a quad light, or a path, at spp 1 use sample 0's stream.
    std::optional<RandomStream> lights;
    if ((!scene.quad_lights.empty() || scene.integrator == Integrator::pathtracer) &&
        averages_samples(view)) {
        lights.emplace(light_random(scene, i, j, 0));
    }
    return camera_ray_colour(render_scene, view, camera_ray(render_scene, i, j),
                             lights ? &*lights : nullptr, observer);
}

Color render_pixel(const RenderScene& render_scene, View view, int i, int j) {
    return render_pixel(render_scene, view, i, j, unobserved());
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
