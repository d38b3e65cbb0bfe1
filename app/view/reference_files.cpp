#include "app/view/reference_files.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "app/compare/reference_image.h"
#include "app/view/file_stamps.h"
#include "base/scene/scene_files.h"
#include "base/scene/scene_loader.h"

#if !defined(_WIN32)
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

extern char** environ;
#endif

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

// Runs `program` with `arguments`, its standard error into `log`; its exit code, 128 plus the
// signal that ended it, or -1 when it could not run. `child` holds its process id while it runs,
// for ReferenceFiles::stop; a child started after `stopping` was set is stopped at once (stop()
// sets `stopping` before it reads `child`, so one of the two sees the other). Not std::system:
// that ignores SIGINT in this process while the child runs, and would lose the Ctrl-C that stops
// the server.
int run_program(const fs::path& program, const std::vector<std::string>& arguments,
                const fs::path& log, std::atomic<long>& child, const std::atomic<bool>& stopping) {
#if defined(_WIN32)
    (void)child;
    (void)stopping;
    std::string command = "\"" + program.string() + "\"";
    for (const std::string& argument : arguments)
        command += " \"" + argument + "\"";
    return std::system((command + " > NUL 2> \"" + log.string() + "\"").c_str());
#else
    std::vector<std::string> words{program.string()};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words)
        argv.push_back(word.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    const int failed = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (failed != 0) return -1;
    child = pid;
    if (stopping) ::kill(pid, SIGTERM);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            child = 0;
            return -1;
        }
    }
    child = 0;
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
#endif
}

std::string file_text(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// What decides the cache's contents: the scene's files and the reference program, by their
// times and sizes.
std::string reference_stamp(const std::string& scene_file, const fs::path& program) {
    std::vector<fs::path> files{program};
    try {
        const std::vector<fs::path> scene = scene_files(load_scene(scene_file));
        files.insert(files.end(), scene.begin(), scene.end());
    } catch (const std::exception&) {
        files.emplace_back(scene_file);
    }
    std::string stamp;
    for (const fs::path& file : files) {
        std::error_code error;
        const auto time = fs::last_write_time(file, error);
        const auto size = error ? 0 : fs::file_size(file, error);
        // libc++ counts file time in __int128, which std::to_string does not take; nanoseconds
        // since 1970 fit a long long until 2262.
        stamp += file.string() + " " +
                 std::to_string(static_cast<long long>(time.time_since_epoch().count())) + " " +
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
    const std::string stamp = reference_stamp(scene_file, reference_program_);
    if (file_text(folder / "stamp") != stamp) {
        std::error_code error;
        fs::remove_all(folder, error);
        fs::create_directories(folder);
        std::ofstream(folder / "stamp", std::ios::binary) << stamp;
    }
    return folder;
}

void ReferenceFiles::stop() {
    stopping_ = true;
#if !defined(_WIN32)
    if (const long pid = child_; pid > 0) ::kill(static_cast<pid_t>(pid), SIGTERM);
#endif
}

void ReferenceFiles::run_reference(const std::vector<std::string>& arguments) {
    const std::string name = reference_program_.filename().string();
    if (stopping_) throw std::runtime_error("raystep view is stopping: " + name + " was not run");
    const fs::path log = cache_ / "last-reference-run.txt";
    const int code = run_program(reference_program_, arguments, log, child_, stopping_);
#if !defined(_WIN32)
    // Ctrl-C in the terminal reaches the whole process group, the reference program first: no
    // other reference run starts after it, whatever the watch loop has seen yet.
    if (code == 128 + SIGINT) stopping_ = true;
#endif
    if (stopping_) throw std::runtime_error("raystep view is stopping: " + name + " was stopped");
    if (code != 0) {
        // Its message without the program's own "raystep: " before it.
        std::string message = file_text(log);
        if (message.rfind("raystep: ", 0) == 0) message.erase(0, 9);
        while (!message.empty() && message.back() == '\n')
            message.pop_back();
        throw std::runtime_error(name + " could not write the reference: " + message);
    }
}

// Runs the reference to write `outputs`, each through a file beside it that is renamed once the
// reference program has finished: a run stopped halfway leaves no image that looks whole.
void ReferenceFiles::write_references(std::vector<std::string> arguments,
                                      const std::vector<fs::path>& outputs) {
    std::vector<fs::path> partial;
    for (const fs::path& output : outputs) {
        partial.push_back(output.parent_path() /
                          (output.stem().string() + ".partial" + output.extension().string()));
        for (std::string& argument : arguments) {
            if (argument == output.string()) argument = partial.back().string();
        }
    }
    run_reference(arguments);
    for (std::size_t k = 0; k < outputs.size(); ++k)
        fs::rename(partial[k], outputs[k]);
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
        write_references(
            {"render", scene_file, "--view", std::string(view_name(view)), "-o", image.string()},
            {image});
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
        const fs::path image = folder / (name + ".full.png");
        write_references({"render", scene_file, "--view", "full", "-o", image.string(),
                          "--trace-data", trace.string()},
                         {image, trace});
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
