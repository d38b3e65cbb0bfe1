#pragma once

#include <string_view>

#include "app/demo/demo_figure.h"

namespace raystep {

// The lecture demos of `raystep demo NAME`, a file per lecture: ray_demos.cpp (stages 2 and 3),
// cost_demos.cpp (stage 4), shading_demos.cpp (stages 5, 6 and 9), sampling_demos.cpp (stage 8),
// path_tracing_demos.cpp (stage 10), surface_detail_demos.cpp (stage 11). Each renders its panels
// at the panel_size its figure needs on an image of `size`, through the stages' public API, so that
// a stage that is not implemented yet stops it with its NotImplemented message.

/// Stage 2: each camera ray's direction as a colour, perspective beside orthographic.
DemoFigure ray_directions_demo(const DemoSize& size);

/// Stage 3: barycentric coordinates (1 - beta - gamma, beta, gamma) as RGB on triangles.
DemoFigure barycentrics_demo(const DemoSize& size);

/// Stage 5: ellipsoids coloured by their normals, taken to the world by M (wrong) beside M^-T.
DemoFigure normal_transform_demo(const DemoSize& size);

/// Stage 3: the mesh of watertight_demo under one triangle test of intersect.h, named as there
/// ("intersect_triangle_cramer"), as one panel captioned with its leaking pixels: the demo with
/// the test as a control, for `raystep view`. Throws std::invalid_argument naming the tests for
/// another name.
DemoFigure watertight_demo_with(std::string_view triangle_test, const DemoSize& size);

/// Stage 4: the BVH's cost per pixel as a heat map, on a bunny and a bunny in a stadium.
DemoFigure bvh_cost_demo(const DemoSize& size);

/// Stage 4: the uniform grid's cost per pixel, on the same scenes and scale as bvh_cost_demo.
DemoFigure grid_cost_demo(const DemoSize& size);

/// Stage 6: one scene's shadows with ray offsets epsilon = 0, too small, good and the error
/// bound, each panel captioned with its pixels of acne.
DemoFigure shadow_acne_demo(const DemoSize& size);

/// Stage 3: a closed mesh far from the origin under the renderer's triangle test beside the
/// lecture's half-space test, the pixels where a ray leaks through the mesh in magenta.
DemoFigure watertight_demo(const DemoSize& size);

/// Stage 8: stripes receding to the horizon at 1, 4 and 16 samples per pixel, a regular grid
/// (aliased) above jittered samples (noise).
DemoFigure aliasing_demo(const DemoSize& size);

/// Stage 8: an area light's soft shadow with 1, 2 x 2, 4 x 4 and 8 x 8 stratified light samples
/// above the same counts at random.
DemoFigure soft_shadows_demo(const DemoSize& size);

/// Stage 10: the Cornell box path-traced by four estimators at 16 paths per pixel (hemisphere,
/// cosine, cosine with light samples, MIS), then MIS at 1 to 64, each captioned with its RMSE
/// against MIS at 576.
DemoFigure path_tracing_demo(const DemoSize& size);

/// Stage 11: a bunny by face normals beside interpolated ones, a wall flat, bump-mapped and
/// normal-mapped, that wall's tangent frames, and textures on a sphere, a plane and a floor.
DemoFigure surface_detail_demo(const DemoSize& size);

/// Stage 9: a glass cube of index 1, 1.33, 1.5 and 2.4, each panel captioned with its critical
/// angle: where the side faces reflect the cube's inside by total internal reflection.
DemoFigure refraction_demo(const DemoSize& size);

}  // namespace raystep
