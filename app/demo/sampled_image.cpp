#include "app/demo/sampled_image.h"

#include "renderer/ray_colour.h"
#include "renderer/sample_streams.h"
#include "renderer/tile_renderer.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

Image sampled_image(const RenderScene& render_scene, SamplePattern pattern, int count,
                    int threads) {
    const Scene& scene = *render_scene.scene;
    const PixelFunction pixel = [&](int i, int j) {
        RandomStream film = film_random(scene, i, j);
        int sample = 0;
        const FilmRadiance radiance = [&](const Vec2& film_point) {
            // Each camera sample its own stream of light samples, as the renderer numbers them
            RandomStream lights = light_random(scene, i, j, sample++);
            const Ray ray = camera_ray_through(render_scene, film_point);
            return full_colour(render_scene, ray, scene_closest_hit(render_scene, ray, nullptr),
                               &lights, unobserved());
        };
        return pixel_colour(radiance, i, j, pattern, count, film);
    };
    return render_pixels(scene.width, scene.height, pixel, threads);
}

}  // namespace raystep
