#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/scene_options.h"

namespace raystep {

/// `raystep trace SCENE X Y [--view VIEW] [--ray-offset RULE [--epsilon E]] [--spp N]
/// [--pixel-sampling PATTERN] [--seed S] [--lookfrom X Y Z] [--compare]`. A pixel with several
/// samples (spp) shows every step of its first sample, each sample's film point and colour, and
/// their mean; quad lights show each light sample's shadow ray, and transmitting surfaces the media
/// on both sides, Fresnel and the refracted ray (render_pixel.h, ray_colour.h).
struct TraceArguments {
    std::string scene;
    int x = 0;
    int y = 0;
    std::string view = "full";
    bool compare = false;
    RayOffsetArguments ray_offset;
    SamplingArguments sampling;
    std::vector<double> lookfrom;  ///< --lookfrom: empty, or the eye in place of the scene's
};

CLI::App* add_trace_command(CLI::App& app, TraceArguments& arguments);

/// Prints the trace: exit code 0, or 1 when a stub or an error stopped it. With --compare, the
/// pixel's values beside the reference's from the scene's reference trace
/// (reference_trace_path), step by step, naming the first that differs: 0 when they are the
/// same, 1 when they differ or a stub stopped this build, 2 when there is no usable reference
/// trace for the scene and pixel (none shipped, a truncated or foreign file, a pixel outside the
/// image, a scene changed since the trace was written).
int run_trace(const TraceArguments& arguments);

}  // namespace raystep
