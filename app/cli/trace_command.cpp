#include "app/cli/trace_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "app/cli/trace_comparison.h"
#include "app/compare/reference_image.h"
#include "app/compare/reference_trace.h"
#include "app/render/pixel_record.h"
#include "app/render/render_pixel.h"
#include "app/render/render_scene.h"
#include "base/errors/input_error.h"
#include "base/errors/not_implemented.h"
#include "base/math/to_text.h"
#include "base/scene/scene_loader.h"

namespace raystep {

namespace {

struct TraceResult {
    std::vector<std::string> lines;
    bool stopped = false;  ///< a stub or an error ended it early
};

TraceResult trace_pixel(const TraceArguments& arguments) {
    Scene scene = load_scene(arguments.scene);
    apply_ray_offset(arguments.ray_offset, scene);
    apply_sampling(arguments.sampling, scene);
    if (arguments.x < 0 || arguments.x >= scene.width || arguments.y < 0 ||
        arguments.y >= scene.height) {
        throw std::invalid_argument("pixel (" + std::to_string(arguments.x) + ", " +
                                    std::to_string(arguments.y) + ") is outside the " +
                                    std::to_string(scene.width) + " x " +
                                    std::to_string(scene.height) + " image of " + scene.path);
    }
    const View view = *parse_view(arguments.view);

    TraceLog log;
    log.add("pixel (" + std::to_string(arguments.x) + ", " + std::to_string(arguments.y) + ") of " +
            scene.path + ", view " + arguments.view);
    TraceResult result;
    try {
        const RenderScene render_scene = prepare_render_scene(scene);
        const Color value =
            render_pixel(render_scene, view, arguments.x, arguments.y, &log, nullptr);
        log.add("value: " + to_text(value) +
                (view == View::depth ? " (t; the image scales it to grey)" : ""));
    } catch (const NotImplemented& stub) {
        log.add(std::string("stopped: ") + stub.what());
        result.stopped = true;
    } catch (const std::exception& error) {
        log.add(std::string("stopped by an error: ") + error.what());
        result.stopped = true;
    }
    result.lines = log.lines();
    return result;
}

// The scene's lights as a trace names them, in the order shade_hit takes them.
std::vector<std::string> light_names(const Scene& scene) {
    std::vector<std::string> names;
    for (const PointLight& light : scene.point_lights)
        names.push_back("point light (line " + std::to_string(light.line) + ")");
    for (const DirectionalLight& light : scene.directional_lights)
        names.push_back("directional light (line " + std::to_string(light.line) + ")");
    return names;
}

// The reference's trace of the scene, checked against the scene and the pixel as it is now;
// InputError, naming the file and the problem, when it cannot serve.
ReferenceTrace reference_trace_for(const TraceArguments& arguments, const Scene& scene, View view) {
    const std::filesystem::path path = reference_trace_path(arguments.scene);
    if (!std::filesystem::exists(path)) {
        throw InputError(
            arguments.scene, 0,
            "no reference trace: --compare reads " + path.string() +
                ", the reference's values of every pixel, which a student release ships for "
                "its own scenes. A scene of your own has none; the reference build writes one "
                "(`raystep-reference render SCENE --view full --trace-data " +
                path.string() + "` in the instructor's repository)");
    }
    ReferenceTrace trace = read_reference_trace(path);
    const std::string file = path.string();
    if (trace.width != scene.width || trace.height != scene.height) {
        throw InputError(file, 0,
                         "recorded for a " + std::to_string(trace.width) + " x " +
                             std::to_string(trace.height) + " image, but " + arguments.scene +
                             " is " + std::to_string(scene.width) + " x " +
                             std::to_string(scene.height) + ": the scene changed since then");
    }
    const std::size_t lights = scene.point_lights.size() + scene.directional_lights.size();
    if (pipeline_reach(trace.view) >= PipelineReach::shading && trace.lights != lights) {
        throw InputError(file, 0,
                         "recorded for " + std::to_string(trace.lights) + " lights, but " +
                             arguments.scene + " has " + std::to_string(lights) +
                             ": the scene changed since then");
    }
    if (pipeline_reach(view) > pipeline_reach(trace.view)) {
        throw InputError(file, 0,
                         "it holds the reference's steps as far as the " +
                             std::string(view_name(trace.view)) + " view takes them; --view " +
                             arguments.view + " goes further: compare with --view " +
                             std::string(view_name(trace.view)) + " or a view before it");
    }
    return trace;
}

// Prints the quantities in three columns, marking the first that differs, and the verdict.
void print_comparison(const TraceComparison& comparison, const std::string& stop) {
    std::size_t quantity = std::string("quantity").size();
    std::size_t ours = std::string("this build").size();
    for (const TraceRow& row : comparison.rows) {
        quantity = std::max(quantity, row.quantity.size());
        ours = std::max(ours, row.ours.size());
    }
    std::printf("   %-*s  %-*s  %s\n", static_cast<int>(quantity), "quantity",
                static_cast<int>(ours), "this build", "reference");
    for (std::size_t k = 0; k < comparison.rows.size(); ++k) {
        const TraceRow& row = comparison.rows[k];
        std::printf("%s %-*s  %-*s  %s\n", comparison.first_difference == k ? ">>" : "  ",
                    static_cast<int>(quantity), row.quantity.c_str(), static_cast<int>(ours),
                    row.ours.c_str(), row.reference.c_str());
    }
    if (comparison.first_difference) {
        const TraceRow& row = comparison.rows[*comparison.first_difference];
        std::printf("first difference: %s, %s here against %s in the reference\n",
                    row.quantity.c_str(), row.ours.c_str(), row.reference.c_str());
    } else if (!comparison.stopped) {
        std::printf("the traces are the same\n");
    }
    if (comparison.stopped) std::printf("stopped: %s\n", stop.c_str());
}

// trace --compare: 0 when this build's pixel is the reference's, 1 when it differs or a stub
// stopped it, 2 when there is nothing to compare with (bad input).
int compare_with_reference(const TraceArguments& arguments) {
    if (!arguments.ray_offset.rule.empty()) {
        std::fprintf(stderr,
                     "raystep: --compare holds this build against the reference's trace, "
                     "recorded with the scene's own ray offset: leave out --ray-offset\n");
        return 2;
    }
    const Scene scene = load_scene(arguments.scene);
    const View view = *parse_view(arguments.view);
    ReferenceTrace reference;
    try {
        if (arguments.x < 0 || arguments.x >= scene.width || arguments.y < 0 ||
            arguments.y >= scene.height) {
            throw InputError(arguments.scene, 0,
                             "pixel (" + std::to_string(arguments.x) + ", " +
                                 std::to_string(arguments.y) + ") is outside its " +
                                 std::to_string(scene.width) + " x " +
                                 std::to_string(scene.height) + " image");
        }
        reference = reference_trace_for(arguments, scene, view);
    } catch (const InputError& error) {
        std::fprintf(stderr, "raystep: %s\n", error.what());
        return 2;
    }

    PixelRecord ours;
    std::string stop;
    try {
        const RenderScene render_scene = prepare_render_scene(scene);
        render_pixel(render_scene, view, arguments.x, arguments.y, nullptr, &ours);
    } catch (const std::exception& error) {
        stop = error.what();
    }
    std::printf("pixel (%d, %d) of %s, view %s, against %s\n", arguments.x, arguments.y,
                arguments.scene.c_str(), arguments.view.c_str(),
                reference_trace_path(arguments.scene).string().c_str());
    // A sampled pixel's samples may come in any order, so no sample of this build need be the
    // reference's first: both records hold the centre ray (render_pixel.h), and what a quad
    // light's random samples decide is left out.
    const bool random_colours = averages_samples(view) && !scene.quad_lights.empty();
    if (averages_samples(view) && scene.samples_per_pixel > 1) {
        std::printf(
            "sampled pixel: compared the ray through the pixel's centre, as at spp 1; the "
            "pixel's %d samples, which may come in any order, are not compared\n",
            scene.samples_per_pixel);
    }
    if (random_colours) {
        std::printf(
            "quad light: compared up to the other lights; the local and full colours hold "
            "its random light samples and are not compared (raystep compare judges "
            "them)\n");
    }
    TraceComparison comparison = compare_pixel(ours, reference.at(arguments.x, arguments.y), view,
                                               light_names(scene), random_colours);
    // An error after the last step the view takes (none do today) still stops the trace.
    comparison.stopped = comparison.stopped || !stop.empty();
    print_comparison(comparison, stop);
    return comparison.first_difference || comparison.stopped ? 1 : 0;
}

}  // namespace

CLI::App* add_trace_command(CLI::App& app, TraceArguments& arguments) {
    CLI::App* command = app.add_subcommand(
        "trace", "Show every step of one pixel: the camera ray, each primitive tested, the hit");
    command->add_option("scene", arguments.scene, "Scene file")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("x", arguments.x, "Pixel column, from 0 at the left")->required();
    command->add_option("y", arguments.y, "Pixel row, from 0 at the top")->required();
    command->add_option("--view", arguments.view, "Which view's computation to trace")
        ->check(CLI::IsMember(view_names()));
    command->add_flag("--compare", arguments.compare,
                      "Hold this build's values of the pixel against the reference's, shipped "
                      "beside the scene as reference/<scene>.trace.exr, and name the first that "
                      "differs");
    add_ray_offset_options(*command, arguments.ray_offset);
    add_sampling_options(*command, arguments.sampling);
    return command;
}

int run_trace(const TraceArguments& arguments) {
    if (arguments.compare) {
        // The reference trace holds the scene's own samples.
        if (arguments.sampling.samples_per_pixel > 0 ||
            !arguments.sampling.pixel_sampling.empty() || arguments.sampling.seed) {
            throw std::invalid_argument(
                "--compare holds the pixel against the scene's own samples: leave out --spp, "
                "--pixel-sampling and --seed");
        }
        return compare_with_reference(arguments);
    }
    const TraceResult ours = trace_pixel(arguments);
    for (const std::string& line : ours.lines)
        std::printf("%s\n", line.c_str());
    return ours.stopped ? 1 : 0;
}

}  // namespace raystep
