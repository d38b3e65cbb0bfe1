#include "app/cli/trace_command.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

#include "app/render/render_pixel.h"
#include "app/render/render_scene.h"
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

// One argument of a command line for the platform's shell, with nothing in it the shell would
// interpret: POSIX single quotes (each ' becomes '\''), or on Windows double quotes around text
// that cmd.exe cannot misread.
std::string shell_argument(const std::string& text) {
#ifdef _WIN32
    if (text.find_first_of("\"%^!") != std::string::npos) {
        throw std::runtime_error("--compare cannot pass " + text +
                                 " to the reference build: rename it without \" % ^ !");
    }
    return "\"" + text + "\"";
#else
    std::string quoted = "'";
    for (const char c : text)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
#endif
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

// A new folder of our own under the system's temporary folder: create_directory fails when the
// name exists, so no one else's file can be there.
std::filesystem::path private_folder() {
    std::random_device entropy;
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::filesystem::path folder =
            std::filesystem::temp_directory_path() / ("raystep-trace-" + std::to_string(entropy()));
        if (std::filesystem::create_directory(folder)) return folder;
    }
    throw std::runtime_error("cannot create a temporary folder for the reference trace");
}

// Runs the reference build's trace of the same pixel and returns its lines.
std::vector<std::string> reference_trace(const TraceArguments& arguments) {
    const std::string executable = reference_executable(arguments);
    std::error_code error;
    if (!std::filesystem::is_regular_file(executable, error)) {
        throw std::runtime_error("the reference build " + executable + " does not exist");
    }
    const std::filesystem::path folder = private_folder();
    const std::filesystem::path output = folder / "trace.txt";
    std::string command = shell_argument(executable) + " trace " + shell_argument(arguments.scene) +
                          " " + std::to_string(arguments.x) + " " + std::to_string(arguments.y) +
                          " --view " + arguments.view + arguments.ray_offset.command_line() +
                          " > " + shell_argument(output.string()) + " 2>&1";
#ifdef _WIN32
    command = "\"" + command + "\"";  // cmd /c strips one outer pair of quotes
#endif
    // The reference exits 1 when its trace stops early; its lines are what matter.
    std::system(command.c_str());

    std::vector<std::string> lines;
    std::ifstream in(output);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    in.close();
    std::filesystem::remove_all(folder, error);
    if (lines.empty()) throw std::runtime_error("the reference build printed no trace: " + command);
    return lines;
}

// Prints both traces in two columns, marking the first line that differs; true when they are
// the same.
bool print_side_by_side(const std::vector<std::string>& ours,
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
        return true;
    }
    std::printf("first difference at line %zu (marked >>)\n", first_difference + 1);
    return false;
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
    add_ray_offset_options(*command, arguments.ray_offset);
    return command;
}

int run_trace(const TraceArguments& arguments) {
    const TraceResult ours = trace_pixel(arguments);
    if (arguments.compare) {
        const bool same = print_side_by_side(ours.lines, reference_trace(arguments));
        return same && !ours.stopped ? 0 : 1;
    }
    for (const std::string& line : ours.lines)
        std::printf("%s\n", line.c_str());
    return ours.stopped ? 1 : 0;
}

}  // namespace raystep
