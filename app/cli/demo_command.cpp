#include "app/cli/demo_command.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "app/cli/output_path.h"
#include "app/demo/demo_list.h"
#include "app/demo/demo_size.h"
#include "app/demo/label_text.h"
#include "base/image/image_io.h"

namespace raystep {

namespace {

void print_list() {
    std::printf("demos (raystep demo NAME [-o FILE] [--size WxH]):\n");
    for (const DemoEntry& demo : demo_list()) {
        std::printf("  %-18s %.*s\n", std::string(demo.name).c_str(),
                    static_cast<int>(demo.description.size()), demo.description.data());
    }
}

}  // namespace

CLI::App* add_demo_command(CLI::App& app, DemoArguments& arguments) {
    CLI::App* command = app.add_subcommand(
        "demo", "Render a labelled image of one lecture idea; without NAME, list them");
    command->add_option("name", arguments.name, "The demo to render")
        ->check(CLI::IsMember(demo_names()));
    command->add_option("-o,--output", arguments.output,
                        "Image file; its extension picks the format. Default: out/demos/NAME.png");
    command
        ->add_option("--size", arguments.size,
                     "Image size in pixels, WIDTHxHEIGHT, from " +
                         demo_size_text(kSmallestDemoSize) + " to " +
                         demo_size_text(kLargestDemoSize) +
                         "; the text grows with the height (1920x1080 for a projector). "
                         "Default: 640x480")
        ->check(CLI::Validator(
            [](std::string& text) {
                try {
                    parse_demo_size(text);
                    return std::string();
                } catch (const std::invalid_argument& problem) {
                    return std::string(problem.what());
                }
            },
            "WxH"));
    command->add_flag("--list", arguments.list, "List the demos with what each shows");
    return command;
}

int run_demo(const DemoArguments& arguments) {
    if (arguments.list || arguments.name.empty()) {
        print_list();
        return 0;
    }
    const DemoEntry& demo = find_demo(arguments.name);
    const std::filesystem::path output = arguments.output.empty()
                                             ? default_output("demos", arguments.name + ".png")
                                             : std::filesystem::path(arguments.output);

    // Labels need a TrueType font; without one the image is still worth having
    const std::optional<LabelFont> font = find_label_font();
    if (!font) {
        std::fprintf(stderr,
                     "raystep: labels left out: OpenImageIO opened none of the fonts %s. On "
                     "Debian or Ubuntu install fonts-dejavu-core.\n",
                     label_fonts_tried().c_str());
    }

    const auto start = std::chrono::steady_clock::now();
    const DemoSize size = arguments.size.empty() ? DemoSize{} : parse_demo_size(arguments.size);
    const Image image = draw_figure(demo.make(size), size, font);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_image(image, output);
    std::printf("wrote %s (%d x %d, demo %s, %.2f s)\n", output.string().c_str(), image.width(),
                image.height(), arguments.name.c_str(), seconds);
    return 0;
}

}  // namespace raystep
