#include "app/probe/render_calls.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/scene/scene_loader.h"
#include "renderer/tile_renderer.h"

namespace raystep::probe {

Image render_for_probe(const RenderQuestion& question) {
    Scene scene = load_scene(question.scene);
    const std::optional<View> view = parse_view(question.view);
    if (!view) throw std::invalid_argument("no such view");
    if (scene.width > question.max_width) {
        const double scale = static_cast<double>(question.max_width) / scene.width;
        scene.width = question.max_width;
        scene.height = std::max(1, static_cast<int>(std::lround(scene.height * scale)));
    }
    // A sampled scene's seed, for renders of one view at several (the grader's noisy render
    // checks).
    if (question.seed) scene.seed = *question.seed;
    if (question.lookfrom) scene.camera.lookfrom = *question.lookfrom;
    if (question.samples_per_pixel) {
        if (*question.samples_per_pixel < 1 || *question.samples_per_pixel > kMaxSamples)
            throw std::invalid_argument("samples_per_pixel out of range");
        scene.samples_per_pixel = *question.samples_per_pixel;
    }
    RenderOptions options;
    options.view = *view;
    options.threads = 1;
    RenderScene render_scene = prepare_render_scene(scene);
    if (question.camera_t_min) render_scene.camera_t_min = *question.camera_t_min;
    if (question.camera_t_max) render_scene.camera_t_max = *question.camera_t_max;
    return render_image(render_scene, options);
}

}  // namespace raystep::probe
