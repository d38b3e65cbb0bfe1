// raystep demo soft-shadows: an area light's penumbra with n x n light samples, stratified and not.

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "renderer/tile_renderer.h"

namespace raystep {

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
