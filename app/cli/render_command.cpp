#include "app/cli/render_command.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "app/cli/output_path.h"
#include "app/compare/reference_trace.h"
#include "base/image/image_io.h"
#include "base/scene/scene_files.h"
#include "base/scene/scene_loader.h"
#include "renderer/pixel_record.h"
#include "renderer/render_pixel.h"
#include "renderer/render_scene.h"
#include "renderer/terminal.h"
#include "renderer/tile_renderer.h"

namespace raystep {

CLI::App* add_render_command(CLI::App& app, RenderArguments& arguments) {
    CLI::App* command = app.add_subcommand("render", "Render a scene to an image file");
    command->add_option("scene", arguments.scene, "Scene file")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("-o,--output", arguments.output,
                        "Image file; its extension picks the format (.png, .exr, ...). "
                        "Default: under out/, the scene's 'output', else SCENE.VIEW.png "
                        "(out/stage6/cornell-box.full.png)");
    command->add_option("--threads", arguments.threads, "Worker threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    command
        ->add_option("--view", arguments.view,
                     "What to show: the stage whose output you want to see")
        ->check(CLI::IsMember(view_names()));
    add_ray_offset_options(*command, arguments.ray_offset);
    add_sampling_options(*command, arguments.sampling);
    add_eye_option(*command, arguments.lookfrom);
    command->add_option("--trace-data", arguments.trace_data,
                        "Also write every pixel's steps (camera ray, hit, lights, colours) to this "
                        "file, the reference trace `trace --compare` reads: a student release "
                        "ships the reference build's as reference/<scene>.trace.exr");
    return command;
}

int run_render(const RenderArguments& arguments) {
    // trace --compare holds a pixel against the scene as it is, ray offset and eye included.
    if (!arguments.trace_data.empty() &&
        (!arguments.ray_offset.rule.empty() || !arguments.lookfrom.empty())) {
        throw std::invalid_argument(
            "--trace-data records the scene as it is: leave out --ray-offset and --lookfrom");
    }
    Scene scene = load_scene(arguments.scene);
    // What the scene asks for that raystep reads but does not render (a CSE168 integrator, say):
    // said before the render, so that an image that lacks it is no surprise.
    for (const SceneNote& note : scene.notes)
        std::fprintf(stderr, "%s\n", warning_text(scene, note).c_str());
    apply_ray_offset(arguments.ray_offset, scene);
    apply_sampling(arguments.sampling, scene);
    apply_eye(arguments.lookfrom, scene);
    const View view = *parse_view(arguments.view);
    if (view == View::indirect && scene.integrator != Integrator::pathtracer) {
        throw std::invalid_argument(
            arguments.scene +
            ": the indirect view shows the light a path tracer brings by more "
            "than one bounce, and this scene is not path-traced (`integrator "
            "pathtracer`)");
    }

    std::filesystem::path output = arguments.output;
    if (output.empty()) {
        const std::filesystem::path scene_file = arguments.scene;
        const std::string file_name =
            scene.output.empty()
                ? scene_file.stem().string() + "." + std::string(view_name(view)) + ".png"
                : scene.output;
        output = default_output(scene_output_folder(scene_file), file_name);
    }

    RenderOptions options;
    options.view = view;
    options.threads = arguments.threads;
    options.progress = is_terminal(stderr);
    options.label = output.filename().string();

    const auto start = std::chrono::steady_clock::now();
    std::vector<PixelRecord> records;
    if (!arguments.trace_data.empty()) options.records = &records;
    const RenderScene render_scene = prepare_render_scene(scene);
    const Image image = render_image(render_scene, options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_image(image, output);

    const unsigned threads = arguments.threads > 0
                                 ? static_cast<unsigned>(arguments.threads)
                                 : std::max(1u, std::thread::hardware_concurrency());
    const std::string samples = averages_samples(view) && scene.samples_per_pixel > 1
                                    ? ", " + std::to_string(scene.samples_per_pixel) + " spp"
                                    : "";
    std::printf("wrote %s (%d x %d, view %s%s, %.2f s on %u thread%s)\n", output.string().c_str(),
                image.width(), image.height(), arguments.view.c_str(), samples.c_str(), seconds,
                threads, threads == 1 ? "" : "s");

    if (!arguments.trace_data.empty()) {
        write_reference_trace(arguments.trace_data, scene.width, scene.height, view,
                              scene.point_lights.size() + scene.directional_lights.size(), records,
                              scene_digest(scene));
        std::printf("wrote %s (the trace data of every pixel)\n", arguments.trace_data.c_str());
    }
    return 0;
}

}  // namespace raystep
