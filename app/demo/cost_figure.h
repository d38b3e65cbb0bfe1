#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "app/demo/demo_figure.h"
#include "renderer/render_scene.h"

namespace raystep {

/// What one ray costs a structure: nodes or cells visited plus primitives tested.
using RayCost = std::function<std::uint64_t(const Ray& ray)>;

/// Builds the structure for a scene and returns its RayCost, which owns it.
using CostStructure = std::function<RayCost(const RenderScene& render_scene)>;

/// The figure of a cost demo: stage 4's bunny close up beside the bunny in a stadium, each pixel
/// coloured by what its camera ray cost `structure`, on a logarithmic scale from 1 to 10^5 that
/// is the same in every cost demo, so that their images compare colour for colour. Each caption
/// gives the mean and the largest cost per pixel.
DemoFigure cost_figure(const DemoSize& size, const std::string& title,
                       const CostStructure& structure);

}  // namespace raystep
