// raystep demo shadow-acne: where a shadow ray starts, and what a fixed epsilon gets wrong.

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "renderer/tile_renderer.h"

namespace raystep {

namespace {

// A pixel is in false shadow when it is this much darker than under the error bound. Lit and
// shadowed differ by the light's whole term (several units at this grazing light), while the
// rules change nothing else: any threshold well inside that gap counts the same pixels.
constexpr double kShadowStep = 0.05;

struct OffsetPanel {
    RayOffset offset;
    const char* label;
};

Image shaded(Scene scene, const RayOffset& offset) {
    scene.ray_offset = offset;
    RenderOptions options;
    options.view = View::shaded;
    return render_image(prepare_render_scene(scene), options);
}

// Pixels darker than in `truth` by more than kShadowStep in any channel.
std::size_t false_shadow_pixels(const Image& image, const Image& truth) {
    std::size_t count = 0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            const Color drop = truth.at(i, j) - image.at(i, j);
            if (drop.r > kShadowStep || drop.g > kShadowStep || drop.b > kShadowStep) ++count;
        }
    }
    return count;
}

}  // namespace

DemoFigure shadow_acne_demo(const DemoSize& size) {
    // Stage 6's acne scene at scale 1e4, where hit points carry rounding errors near 1e-8 and a
    // light grazes the floor at 3 degrees. `raystep bench --epsilon` measures that the error bound
    // gets every pixel of it right (docs/stage6.md, "Measuring acne"), so the pixels that another
    // rule makes darker are its acne. Along the ray, epsilon = 1e-12 still has acne there, and
    // 1e-3 is inside the range (1e-8 to 1e-1) that has neither acne nor leaks.
    const PanelSize panel = panel_size(size, 4, false);
    const Scene scene = load_demo_scene("stage6/acne-scale-1e4.test", panel);
    const Image truth = shaded(scene, {OffsetRule::error_bound, 0.0});
    const OffsetPanel fixed[] = {
        {{OffsetRule::along_ray, 0.0}, "epsilon = 0"},
        {{OffsetRule::along_ray, 1e-12}, "epsilon = 1e-12 along the ray"},
        {{OffsetRule::along_ray, 1e-3}, "epsilon = 1e-3 along the ray"},
    };

    DemoFigure figure;
    figure.title =
        "Shadow acne against epsilon: a sphere and a slab at scale 1e4, light at 3 degrees";
    for (const OffsetPanel& p : fixed) {
        Image image = shaded(scene, p.offset);
        const std::size_t acne = false_shadow_pixels(image, truth);
        figure.panels.push_back({std::string(p.label) + ": " + thousands(acne) +
                                     (acne == 1 ? " pixel" : " pixels") + " of acne",
                                 std::move(image)});
    }
    figure.panels.push_back({"error bound, no epsilon: no acne", truth});
    return figure;
}

}  // namespace raystep
