// raystep demo aliasing: what one ray per pixel does to a pattern finer than the pixels.

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "app/demo/sampled_image.h"

namespace raystep {

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

}  // namespace raystep
