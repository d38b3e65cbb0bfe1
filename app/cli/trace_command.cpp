#include "app/cli/trace_command.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "app/compare/reference_image.h"
#include "app/trace/pixel_trace.h"
#include "base/errors/input_error.h"
#include "base/scene/scene_loader.h"

namespace raystep {

namespace {

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
    if (!arguments.ray_offset.rule.empty() || !arguments.lookfrom.empty()) {
        std::fprintf(stderr,
                     "raystep: --compare holds this build against the reference's trace, "
                     "recorded from the scene as it is: leave out --ray-offset and --lookfrom\n");
        return 2;
    }
    const Scene scene = load_scene(arguments.scene);
    const View view = *parse_view(arguments.view);
    PixelComparison result;
    try {
        result = compare_pixel_with_reference(scene, view, arguments.x, arguments.y,
                                              reference_trace_path(arguments.scene));
    } catch (const InputError& error) {
        std::fprintf(stderr, "raystep: %s\n", error.what());
        return 2;
    }
    std::printf("pixel (%d, %d) of %s, view %s, against %s\n", arguments.x, arguments.y,
                arguments.scene.c_str(), arguments.view.c_str(),
                result.reference_trace.string().c_str());
    for (const std::string& note : result.notes)
        std::printf("%s\n", note.c_str());
    print_comparison(result.comparison, result.stop);
    return result.comparison.first_difference || result.comparison.stopped ? 1 : 0;
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
    add_eye_option(*command, arguments.lookfrom);
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
    Scene scene = load_scene(arguments.scene);
    apply_ray_offset(arguments.ray_offset, scene);
    apply_sampling(arguments.sampling, scene);
    apply_eye(arguments.lookfrom, scene);
    const PixelTrace ours =
        trace_pixel(scene, *parse_view(arguments.view), arguments.x, arguments.y);
    for (const std::string& line : ours.lines)
        std::printf("%s\n", line.c_str());
    return ours.stopped ? 1 : 0;
}

}  // namespace raystep
