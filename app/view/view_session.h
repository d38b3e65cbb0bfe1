#pragma once

#include <cstdint>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/view/file_stamps.h"
#include "app/view/live_render.h"
#include "base/scene/scene.h"

namespace raystep {

/// What the page asked to see last: the view and the controls' values (scene_controls.h).
struct ViewRequest {
    View view = View::full;
    std::map<std::string, std::string> controls;
};

/// The scene `raystep view` shows and its render: what the page's requests change, shared by the
/// server's threads. Its scene can be any under the project's scenes/ folder (the page's list) or
/// the one given on the command line; it is read again when one of its files changes.
class ViewSession {
  public:
    ViewSession(std::filesystem::path project, int threads);

    /// Opens a scene file. Rethrows what loading it threw: InputError naming file:line.
    void open(const std::string& scene_file);

    /// Opens `relative`, a scene of the project's scenes/ folder as scene_list names it. Throws
    /// std::invalid_argument for any other name: the page can read no file outside that list.
    void open_listed(const std::string& relative);

    /// The project's scenes, relative to its scenes/ folder, sorted: the .test files under it,
    /// except links to a file outside it and files whose names are not UTF-8.
    std::vector<std::string> scene_list() const;

    /// Starts rendering what `request` asks for. Throws std::invalid_argument for a control's bad
    /// value, and when the scene did not load.
    std::uint64_t render(const ViewRequest& request);

    /// When a scene file changed: reads it again (keeping the error, file:line, when it no longer
    /// loads) and renders the last request again. True when it did.
    bool reload_if_changed();

    /// The scene as loaded, with the controls' values applied; throws std::invalid_argument when
    /// it did not load or a control's value is bad.
    Scene scene_with(const std::map<std::string, std::string>& controls) const;

    /// The scene file, as given or as the project's scenes/ list resolves it.
    std::string scene_file() const;
    /// The scene as loaded; nullopt, with load_error(), when it did not load.
    std::optional<Scene> scene() const;
    std::string load_error() const;
    /// Counts the scene's loads, so that the page knows when to ask again.
    std::uint64_t scene_generation() const;
    /// The controls' values of the last render asked for (none before the first), so that every
    /// page can show what the one image it renders was rendered with.
    std::map<std::string, std::string> last_controls() const;

    LiveRender& live() { return live_; }

  private:
    void load(const std::string& scene_file);

    std::filesystem::path project_;
    int threads_;
    mutable std::mutex mutex_;
    std::string scene_file_;
    std::optional<Scene> scene_;
    std::string load_error_;
    std::exception_ptr load_failure_;
    std::uint64_t scene_generation_ = 0;
    FileStamps stamps_;
    std::optional<ViewRequest> last_request_;
    LiveRender live_;
};

}  // namespace raystep
