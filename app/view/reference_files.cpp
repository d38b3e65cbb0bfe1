#include "app/view/reference_files.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "app/compare/reference_image.h"
#include "app/view/file_stamps.h"
#include "base/scene/scene_loader.h"

namespace raystep {

namespace {

namespace fs = std::filesystem;

// True when a release's reference/ folder holds the scene's trace or an image of it.
bool shipped(const std::string& scene_file) {
    if (fs::exists(reference_trace_path(scene_file))) return true;
    try {
        for (const std::string& view : reference_views(scene_file)) {
            if (fs::exists(reference_image_path(scene_file, view))) return true;
        }
    } catch (const std::exception&) {
        // A `# views:` line naming no view: the scene's own error, which loading it reports.
    }
    return false;
}

// One word for the shell: in single quotes, each quote in it closed, escaped and reopened.
std::string shell_word(const std::string& word) {
    std::string quoted = "'";
    for (const char c : word)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::string file_text(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// What decides the cache's contents: the scene's files and the reference program, by their
// times and sizes.
std::string stamp_of(const std::string& scene_file, const fs::path& program) {
    std::vector<fs::path> files{program};
    try {
        const std::vector<fs::path> scene = scene_files(scene_file, load_scene(scene_file));
        files.insert(files.end(), scene.begin(), scene.end());
    } catch (const std::exception&) {
        files.emplace_back(scene_file);
    }
    std::string stamp;
    for (const fs::path& file : files) {
        std::error_code error;
        const auto time = fs::last_write_time(file, error);
        const auto size = error ? 0 : fs::file_size(file, error);
        stamp += file.string() + " " + std::to_string(time.time_since_epoch().count()) + " " +
                 std::to_string(size) + "\n";
    }
    return stamp;
}

}  // namespace

ReferenceFiles::ReferenceFiles(fs::path reference_program, fs::path cache)
    : reference_program_(std::move(reference_program)), cache_(std::move(cache)) {}

bool ReferenceFiles::can_write() const {
    std::error_code error;
    return !reference_program_.empty() && fs::is_regular_file(reference_program_, error);
}

std::vector<std::string> ReferenceFiles::views(const std::string& scene_file) const {
    std::vector<std::string> views;
    if (can_write() && !shipped(scene_file)) return view_names();
    for (const std::string& view : view_names()) {
        if (fs::exists(reference_image_path(scene_file, view))) views.push_back(view);
    }
    return views;
}

std::string ReferenceFiles::source(const std::string& scene_file) const {
    if (shipped(scene_file)) return "shipped beside the scene";
    if (can_write()) return "written by " + reference_program_.filename().string();
    return "";
}

fs::path ReferenceFiles::cache_folder(const std::string& scene_file) const {
    // One folder per scene file, named by its absolute path's hash and its own name.
    std::error_code error;
    const std::string absolute = fs::absolute(scene_file, error).lexically_normal().string();
    const std::size_t hash = std::hash<std::string>{}(absolute);
    char name[32];
    std::snprintf(name, sizeof name, "%016zx", hash);
    return cache_ / (fs::path(scene_file).stem().string() + "-" + name) / "reference";
}

fs::path ReferenceFiles::fresh_cache_folder(const std::string& scene_file) {
    const fs::path folder = cache_folder(scene_file);
    const std::string stamp = stamp_of(scene_file, reference_program_);
    if (file_text(folder / "stamp") != stamp) {
        std::error_code error;
        fs::remove_all(folder, error);
        fs::create_directories(folder);
        std::ofstream(folder / "stamp", std::ios::binary) << stamp;
    }
    return folder;
}

void ReferenceFiles::run_reference(const std::vector<std::string>& arguments) const {
    std::string command = shell_word(reference_program_.string());
    for (const std::string& argument : arguments)
        command += " " + shell_word(argument);
    const fs::path log = cache_ / "last-reference-run.txt";
    command += " > " + shell_word(log.string()) + " 2>&1";
    if (std::system(command.c_str()) != 0) {
        throw std::runtime_error(reference_program_.filename().string() +
                                 " failed: " + file_text(log));
    }
}

fs::path ReferenceFiles::image(const std::string& scene_file, View view) {
    const fs::path shipped_image = reference_image_path(scene_file, view_name(view));
    if (fs::exists(shipped_image) || shipped(scene_file) || !can_write()) {
        return fs::exists(shipped_image) ? shipped_image : fs::path();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    const fs::path folder = fresh_cache_folder(scene_file);
    const fs::path image = folder / (fs::path(scene_file).stem().string() + "." +
                                     std::string(view_name(view)) + ".png");
    if (!fs::exists(image)) {
        run_reference(
            {"render", scene_file, "--view", std::string(view_name(view)), "-o", image.string()});
    }
    return image;
}

fs::path ReferenceFiles::trace(const std::string& scene_file) {
    const fs::path shipped_trace = reference_trace_path(scene_file);
    if (fs::exists(shipped_trace) || shipped(scene_file) || !can_write()) return shipped_trace;
    std::lock_guard<std::mutex> lock(mutex_);
    const fs::path folder = fresh_cache_folder(scene_file);
    const std::string name = fs::path(scene_file).stem().string();
    const fs::path trace = folder / (name + ".trace.exr");
    if (!fs::exists(trace)) {
        run_reference({"render", scene_file, "--view", "full", "-o",
                       (folder / (name + ".full.png")).string(), "--trace-data", trace.string()});
    }
    return trace;
}

fs::path reference_program_beside(const fs::path& program) {
    if (program.empty()) return {};
#if defined(_WIN32)
    const fs::path reference = program.parent_path() / "raystep-reference.exe";
#else
    const fs::path reference = program.parent_path() / "raystep-reference";
#endif
    std::error_code error;
    return fs::is_regular_file(reference, error) ? reference : fs::path();
}

}  // namespace raystep
