// raystep demo ray-directions: what stage 2's cameras make, before anything is hit.

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"

namespace raystep {

DemoFigure ray_directions_demo(const DemoSize& size) {
    // The two cameras of stage 2's scenes. The rays view colours a direction d as (d + 1) / 2:
    // red grows to the right, green upwards, and -z (straight ahead) is (0.5, 0.5, 0).
    const PanelSize panel = panel_size(size, 2, false);
    DemoFigure figure;
    figure.title = "Ray directions as colour: (d + 1) / 2, red = x, green = y, blue = z";
    figure.panels.push_back(view_panel("stage2/perspective-wide.test", panel, View::rays,
                                       "perspective: a direction per pixel"));
    figure.panels.push_back(view_panel("stage2/orthographic.test", panel, View::rays,
                                       "orthographic: one direction, one colour"));
    return figure;
}

}  // namespace raystep
