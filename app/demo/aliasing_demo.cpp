// raystep demo aliasing: what one ray per pixel does to a pattern finer than the pixels.

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "app/render/ray_colour.h"
#include "app/render/sample_streams.h"
#include "app/render/tile_renderer.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

namespace {

struct SamplingPanel {
    SamplePattern pattern;
    int count;
    const char* caption;
};

// The full view with `count` samples per pixel placed by `pattern`, through stage 8's
// pixel_colour for every panel, one sample too: the renderer takes the pixel's centre at spp 1
// whatever the pattern, and a single jittered sample (one random point of the pixel) is half of
// what this demo shows. The film points come from the renderer's streams (sample_streams.h).
Image sampled_image(const RenderScene& render_scene, SamplePattern pattern, int count) {
    const Scene& scene = *render_scene.scene;
    const PixelFunction pixel = [&](int i, int j) {
        RandomStream film = film_random(scene, i, j);
        const FilmRadiance radiance = [&](const Vec2& film_point) {
            const Ray ray = camera_ray_through(render_scene, film_point);
            return full_colour(render_scene, ray, scene_closest_hit(render_scene, ray, nullptr),
                               nullptr, nullptr, nullptr);
        };
        return pixel_colour(radiance, i, j, pattern, count, film);
    };
    return render_pixels(scene.width, scene.height, pixel, 0);
}

}  // namespace

DemoFigure aliasing_demo(const DemoSize& size) {
    // scenes/demos/aliasing.test: white bands one unit apart receding to the horizon, in flat
    // colours. Top row, the regular grid: its moire moves towards the horizon as the grid gets
    // finer but never leaves, since the bands always get finer still. Bottom row, jittered: the
    // same samples per pixel turn the false bands into noise, and 16 of them into the grey the
    // pattern averages to.
    const PanelSize panel = panel_size(size, 6, false);
    const Scene scene = load_demo_scene("demos/aliasing.test", panel);
    const RenderScene render_scene = prepare_render_scene(scene);
    const SamplingPanel panels[] = {
        {SamplePattern::regular, 1, "regular, 1 spp (the centre)"},
        {SamplePattern::regular, 4, "regular, 4 spp (2 x 2)"},
        {SamplePattern::regular, 16, "regular, 16 spp (4 x 4)"},
        {SamplePattern::jittered, 1, "jittered, 1 spp"},
        {SamplePattern::jittered, 4, "jittered, 4 spp (2 x 2)"},
        {SamplePattern::jittered, 16, "jittered, 16 spp (4 x 4)"},
    };

    DemoFigure figure;
    figure.title = "Aliasing against samples per pixel: stripes receding to the horizon";
    for (const SamplingPanel& p : panels) {
        figure.panels.push_back({p.caption, sampled_image(render_scene, p.pattern, p.count)});
    }
    return figure;
}

}  // namespace raystep
