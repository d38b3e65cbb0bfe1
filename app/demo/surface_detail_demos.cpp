// The demo of stage 11: what the lookups after the hit change, each beside what the surface is
// without them.

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"

namespace raystep {

DemoFigure surface_detail_demo(const DemoSize& size) {
    // Top: the same bunny shaded by its faces' normals and by normals interpolated from its
    // vertices (stage11/smooth-bunny.test); one wall flat, bump-mapped and normal-mapped from the
    // same bricks (stage11/bumps.test), where the light grazes the bevels. Bottom: that wall's
    // tangent frames, the axes the maps are read along; textures on a sphere, a mirrored wall and
    // a repeated floor (stage11/textured.test).
    const PanelSize panel = panel_size(size, 4, false);
    DemoFigure figure;
    figure.title = "Surface detail: smooth normals, bump and normal maps, textures";
    figure.panels.push_back(view_panel("stage11/smooth-bunny.test", panel, View::shaded,
                                       "face normals | interpolated normals"));
    figure.panels.push_back(
        view_panel("stage11/bumps.test", panel, View::shaded, "no map | bump map | normal map"));
    figure.panels.push_back(view_panel("stage11/bumps.test", panel, View::tangent,
                                       "the tangent frames the maps are read in"));
    figure.panels.push_back(view_panel("stage11/textured.test", panel, View::shaded,
                                       "textures: sphere uvs, mirrored, repeated"));
    return figure;
}

}  // namespace raystep
