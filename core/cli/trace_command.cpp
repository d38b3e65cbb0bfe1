#include "core/cli/trace_command.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

#include "core/errors/not_implemented.h"
#include "core/math/to_text.h"
#include "core/render/render_pixel.h"
#include "core/render/render_scene.h"
#include "core/scene/scene_loader.h"

namespace raystep {

namespace {

struct TraceResult {
    std::vector<std::string> lines;
    bool stopped = false;  ///< a stub or an error ended it early
};

TraceResult trace_pixel(const TraceArguments& arguments) {
    const Scene scene = load_scene(arguments.scene);
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
        const Color value = render_pixel(render_scene, view, arguments.x, arguments.y, &log);
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

std::string quoted(const std::string& text) {
    return "\"" + text + "\"";
}

std::string reference_executable(const TraceArguments& arguments) {
    if (!arguments.reference.empty()) return arguments.reference;
#ifdef RAYSTEP_REFERENCE_EXECUTABLE
    return RAYSTEP_REFERENCE_EXECUTABLE;
#else
    throw std::runtime_error(
        "--compare needs the reference build (raystep-reference), which this repository does not "
        "have; give its path with --reference");
#endif
}

// Runs the reference build's trace of the same pixel and returns its lines.
std::vector<std::string> reference_trace(const TraceArguments& arguments) {
    const std::string executable = reference_executable(arguments);
    if (!std::filesystem::exists(executable)) {
        throw std::runtime_error("the reference build " + executable + " does not exist");
    }
    std::random_device entropy;
    const std::filesystem::path output = std::filesystem::temp_directory_path() /
                                         ("raystep-trace-" + std::to_string(entropy()) + ".txt");
    const std::string command = quoted(executable) + " trace " + quoted(arguments.scene) + " " +
                                std::to_string(arguments.x) + " " + std::to_string(arguments.y) +
                                " --view " + arguments.view + " > " + quoted(output.string()) +
                                " 2>&1";
    // std::system hands the line to the platform's shell, the same on Linux, macOS and Windows.
    std::system(command.c_str());

    std::vector<std::string> lines;
    std::ifstream in(output);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    in.close();
    std::filesystem::remove(output);
    if (lines.empty()) throw std::runtime_error("the reference build printed no trace: " + command);
    return lines;
}

void print_side_by_side(const std::vector<std::string>& ours,
                        const std::vector<std::string>& reference) {
    std::size_t width = std::string("this build").size();
    for (const std::string& line : ours)
        width = std::max(width, line.size());

    const std::size_t rows = std::max(ours.size(), reference.size());
    std::size_t first_difference = rows;
    for (std::size_t k = 0; k < rows; ++k) {
        const std::string left = k < ours.size() ? ours[k] : "";
        const std::string right = k < reference.size() ? reference[k] : "";
        if (left != right) {
            first_difference = k;
            break;
        }
    }

    std::printf("   %-*s | %s\n", static_cast<int>(width), "this build", "reference");
    for (std::size_t k = 0; k < rows; ++k) {
        const std::string left = k < ours.size() ? ours[k] : "";
        const std::string right = k < reference.size() ? reference[k] : "";
        std::printf("%s %-*s | %s\n", k == first_difference ? ">>" : "  ", static_cast<int>(width),
                    left.c_str(), right.c_str());
    }
    if (first_difference == rows) {
        std::printf("the traces are the same\n");
    } else {
        std::printf("first difference at line %zu (marked >>)\n", first_difference + 1);
    }
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
                      "Print the reference build's trace beside this build's, marking the first "
                      "line where they differ");
    command->add_option("--reference", arguments.reference,
                        "The reference raystep to compare with (default: the one built here)");
    return command;
}

int run_trace(const TraceArguments& arguments) {
    const TraceResult ours = trace_pixel(arguments);
    if (arguments.compare) {
        print_side_by_side(ours.lines, reference_trace(arguments));
    } else {
        for (const std::string& line : ours.lines)
            std::printf("%s\n", line.c_str());
    }
    return ours.stopped ? 1 : 0;
}

}  // namespace raystep
