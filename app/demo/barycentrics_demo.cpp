// raystep demo barycentrics: the beta and gamma that stage 3's triangle tests return.

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"

namespace raystep {

DemoFigure barycentrics_demo(const DemoSize& size) {
    // Stage 3's scenes: each triangle runs from red at p0 through green at p1 to blue at p2, so
    // shared edges show as seams, and a pixel of background on a seam would be a leak.
    const PanelSize panel = panel_size(size, 2, false);
    DemoFigure figure;
    figure.title = "Barycentric coordinates as colour: RGB = (1 - beta - gamma, beta, gamma)";
    figure.panels.push_back(view_panel("stage3/triangle-fan.test", panel, View::barycentric,
                                       "eight triangles around one vertex"));
    figure.panels.push_back(view_panel("stage3/quad-oblique.test", panel, View::barycentric,
                                       "a square of two triangles, seen obliquely"));
    return figure;
}

}  // namespace raystep
