#include "app/view/view_session.h"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <system_error>

#include <nlohmann/json.hpp>

#include "app/view/scene_controls.h"
#include "base/scene/scene_files.h"
#include "base/scene/scene_loader.h"

namespace raystep {

namespace {

bool is_utf8(const std::string& text) {
    try {
        (void)nlohmann::json(text).dump();
        return true;
    } catch (const nlohmann::json::type_error&) {
        return false;
    }
}

}  // namespace

ViewSession::ViewSession(std::filesystem::path project, int threads)
    : project_(std::move(project)), threads_(threads) {}

void ViewSession::load(const std::string& scene_file) {
    std::optional<Scene> scene;
    std::string error;
    std::exception_ptr failure;
    try {
        scene = load_scene(scene_file);
    } catch (const std::exception& problem) {
        error = problem.what();
        failure = std::current_exception();
    }
    // The stamps are taken before the next edit can land, from the files this load read.
    FileStamps stamps(scene ? scene_files(*scene) : std::vector<std::filesystem::path>{scene_file});
    std::lock_guard<std::mutex> lock(mutex_);
    if (scene_file != scene_file_) last_request_.reset();
    scene_file_ = scene_file;
    scene_ = std::move(scene);
    load_error_ = error;
    load_failure_ = failure;
    stamps_ = std::move(stamps);
    ++scene_generation_;
}

void ViewSession::open(const std::string& scene_file) {
    live_.stop();
    load(scene_file);
    std::lock_guard<std::mutex> lock(mutex_);
    if (load_failure_) std::rethrow_exception(load_failure_);
}

std::vector<std::string> ViewSession::scene_list() const {
    std::vector<std::string> scenes;
    const std::filesystem::path folder = project_ / "scenes";
    std::error_code error;
    const std::filesystem::path real_folder = std::filesystem::weakly_canonical(folder, error);
    for (auto it = std::filesystem::recursive_directory_iterator(folder, error);
         !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
        if (!it->is_regular_file() || it->path().extension() != ".test") continue;
        // A link to a file outside scenes/ is not the project's scene: the page never reads it,
        // nor shows its lines in a load error.
        std::error_code ignored;
        const std::filesystem::path real = std::filesystem::weakly_canonical(it->path(), ignored);
        const std::filesystem::path inside = real.lexically_relative(real_folder);
        if (ignored || inside.empty() || *inside.begin() == "..") continue;
        // A name the page can send back: JSON carries only UTF-8 text.
        const std::string name = it->path().lexically_relative(folder).generic_string();
        if (is_utf8(name)) scenes.push_back(name);
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

void ViewSession::open_listed(const std::string& relative) {
    const std::vector<std::string> scenes = scene_list();
    if (std::find(scenes.begin(), scenes.end(), relative) == scenes.end()) {
        throw std::invalid_argument("no scene '" + relative + "' under " +
                                    (project_ / "scenes").string());
    }
    live_.stop();
    // Named from the current folder when it is under it, as a scene given on the command line is.
    std::error_code error;
    const std::filesystem::path file = project_ / "scenes" / relative;
    const std::filesystem::path near = std::filesystem::relative(file, error);
    const bool under = !error && !near.empty() && *near.begin() != "..";
    load((under ? near : file).string());
}

Scene ViewSession::scene_with(const std::map<std::string, std::string>& controls) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!scene_) throw std::invalid_argument(load_error_);
    Scene scene = *scene_;
    apply_scene_controls(controls, scene);
    return scene;
}

std::uint64_t ViewSession::render(const ViewRequest& request) {
    Scene scene = scene_with(request.controls);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        last_request_ = request;
    }
    return live_.start(std::move(scene), request.view, threads_);
}

bool ViewSession::reload_if_changed() {
    std::string file;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (scene_file_.empty() || !stamps_.changed()) return false;
        file = scene_file_;
    }
    live_.stop();
    load(file);
    std::optional<ViewRequest> request;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        request = last_request_;
    }
    if (request && scene()) {
        try {
            render(*request);
        } catch (const std::invalid_argument&) {
            // A control the edited scene no longer takes: the page asks again with its values.
        }
    }
    return true;
}

std::string ViewSession::scene_file() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return scene_file_;
}

std::optional<Scene> ViewSession::scene() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return scene_;
}

std::string ViewSession::load_error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return load_error_;
}

std::uint64_t ViewSession::scene_generation() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return scene_generation_;
}

std::map<std::string, std::string> ViewSession::last_controls() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_request_ ? last_request_->controls : std::map<std::string, std::string>{};
}

}  // namespace raystep
