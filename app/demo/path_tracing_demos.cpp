// The demo of stage 10: the path tracer's estimators side by side at equal samples, and one of
// them converging.

#include <cstdio>

#include "app/compare/image_diff.h"
#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "renderer/tile_renderer.h"

namespace raystep {

namespace {

struct Estimator {
    DirectionSampling sampling;
    NextEvent next_event;
    const char* name;
};

Image path_traced(Scene scene, const Estimator& estimator, int samples) {
    scene.importance_sampling = estimator.sampling;
    scene.next_event = estimator.next_event;
    scene.samples_per_pixel = samples;
    return render_image(prepare_render_scene(scene), RenderOptions{});
}

std::string caption(const std::string& text, const Image& image, const Image& converged) {
    char rmse[64];
    std::snprintf(rmse, sizeof rmse, ", RMSE %.3f",
                  compare_images(converged, image, 0.02f).rms_error);
    return text + rmse;
}

}  // namespace

DemoFigure path_tracing_demo(const DemoSize& size) {
    // scenes/stage10/cornell-box.test, path-traced with no depth limit and Russian roulette. Top
    // row, 16 paths per pixel by each estimator: directions uniform over the hemisphere and
    // cosine-weighted, lit only where a path hits the light; cosine with a light sample at each
    // hit (next event estimation); BRDF sampling and light sampling weighted by MIS. Bottom row,
    // MIS at 1, 4, 16 and 64 paths: the noise halves for every fourfold. Each caption gives the
    // RMSE against MIS at 576 paths (24 x 24), whose own noise, a third of the 64-path panel's,
    // adds 5% to that panel's RMSE and less to the others'.
    const PanelSize panel = panel_size(size, 8, false);
    const Scene scene = load_demo_scene("stage10/cornell-box.test", panel);
    const Estimator estimators[] = {
        {DirectionSampling::hemisphere, NextEvent::off, "hemisphere"},
        {DirectionSampling::cosine, NextEvent::off, "cosine"},
        {DirectionSampling::cosine, NextEvent::on, "cosine + light"},
        {DirectionSampling::brdf, NextEvent::mis, "MIS"},
    };
    const Estimator& mis = estimators[3];
    const Image converged = path_traced(scene, mis, 576);

    DemoFigure figure;
    figure.title = "Path tracing: four estimators at 16 paths per pixel (top); MIS converging";
    for (const Estimator& estimator : estimators) {
        const Image image = path_traced(scene, estimator, 16);
        figure.panels.push_back({caption(estimator.name, image, converged), image});
    }
    for (const int samples : {1, 4, 16, 64}) {
        const Image image = path_traced(scene, mis, samples);
        figure.panels.push_back(
            {caption("MIS, " + std::to_string(samples) + " spp", image, converged), image});
    }
    return figure;
}

}  // namespace raystep
