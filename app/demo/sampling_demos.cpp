// The demos of stage 8: what one ray per pixel does to a fine pattern, and an area light's
// penumbra.

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "app/demo/sampled_image.h"
#include "renderer/tile_renderer.h"

namespace raystep {

// raystep demo aliasing: what one ray per pixel does to a pattern finer than the pixels.

namespace {

struct SamplingPanel {
    SamplePattern pattern;
    int count;
    const char* caption;
};

}  // namespace

DemoFigure aliasing_demo(const DemoSize& size) {
    // scenes/demos/aliasing.test: white bands one unit apart receding to the horizon, in flat
    // colours. Top row, the regular grid: its moire moves towards the horizon as the grid gets
    // finer but never leaves, since the bands always get finer still. Bottom row, jittered: the
    // same samples per pixel turn the false bands into noise, and 16 of them into the grey the
    // pattern averages to. Every panel goes through stage 8's pixel_colour (sampled_image), so
    // that one jittered sample is a random point of the pixel, not the renderer's centre.
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
        figure.panels.push_back({p.caption, sampled_image(render_scene, p.pattern, p.count, 0)});
    }
    return figure;
}

// raystep demo soft-shadows: an area light's penumbra with n x n light samples, stratified and not.

namespace {

Image with_light_samples(Scene scene, int count, bool stratified) {
    scene.light_samples = count;
    scene.light_stratify = stratified;
    return render_image(prepare_render_scene(scene), RenderOptions{});
}

}  // namespace

DemoFigure soft_shadows_demo(const DemoSize& size) {
    // scenes/demos/soft-shadows.test: a sphere and a post under a square light, one ray per
    // pixel, so that every difference between the panels is the light's samples. Top row,
    // stratified (`lightstratify on`): n x n strata of the light, one jittered sample in each;
    // bottom row, the same counts placed at random. One sample is a hard shadow either way.
    const PanelSize panel = panel_size(size, 8, false);
    Scene scene = load_demo_scene("demos/soft-shadows.test", panel);
    scene.samples_per_pixel = 1;
    const int sides[] = {1, 2, 4, 8};

    DemoFigure figure;
    figure.title = "Soft shadows against light samples: stratified (top), random (bottom)";
    for (const int n : sides) {
        const std::string grid = std::to_string(n) + " x " + std::to_string(n);
        figure.panels.push_back({"stratified " + grid, with_light_samples(scene, n * n, true)});
    }
    for (const int n : sides) {
        figure.panels.push_back(
            {"random " + std::to_string(n * n), with_light_samples(scene, n * n, false)});
    }
    return figure;
}

}  // namespace raystep
