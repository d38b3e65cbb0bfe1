#pragma once

#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "renderer/view.h"

namespace raystep {

/// Where the page's reference for a scene comes from. A student release ships the reference's
/// images and trace beside each scene (reference/, app/compare/reference_image.h): those come
/// first. The instructor's build has no such folders but has the reference program beside its
/// own (`raystep-reference`): it writes them, as the release writer does, on first use into a
/// cache, and again when the scene's files or that program change.
class ReferenceFiles {
  public:
    /// `reference_program` may be empty or missing: then only shipped files serve. `cache` is the
    /// folder the reference program writes into.
    ReferenceFiles(std::filesystem::path reference_program, std::filesystem::path cache);

    /// The views of the scene that have, or can have, a reference image.
    std::vector<std::string> views(const std::string& scene_file) const;

    /// The reference image of the view, written first when it must be; empty when there is none.
    /// Throws std::runtime_error with the reference program's words when it fails.
    std::filesystem::path image(const std::string& scene_file, View view);

    /// The reference trace of the scene (every pixel's values, as far as the full view goes),
    /// written first when it must be; the shipped path, which may not exist, when no reference
    /// program can write one.
    std::filesystem::path trace(const std::string& scene_file);

    /// Where the reference comes from, for the page: "shipped beside the scene", "written by
    /// raystep-reference", or empty when there is none.
    std::string source(const std::string& scene_file) const;

    /// Stops the reference program under way, if any, and runs none after it: image and trace
    /// then throw. For Ctrl-C, which must not wait minutes for a reference of a slow scene.
    void stop();

  private:
    bool can_write() const;
    std::filesystem::path cache_folder(const std::string& scene_file) const;
    /// The cache folder for the scene, emptied first when its stamp is stale.
    std::filesystem::path fresh_cache_folder(const std::string& scene_file);
    void run_reference(const std::vector<std::string>& arguments);
    void write_references(std::vector<std::string> arguments,
                          const std::vector<std::filesystem::path>& outputs);

    std::filesystem::path reference_program_;
    std::filesystem::path cache_;
    std::mutex mutex_;                   ///< one reference run at a time
    std::atomic<long> child_{0};         ///< the reference program's process id while it runs
    std::atomic<bool> stopping_{false};  ///< set by stop(), or by a Ctrl-C that ended the child
};

/// The reference program that sits beside `program` in an instructor's build: `raystep-reference`
/// in the same folder; empty when there is none (a student release).
std::filesystem::path reference_program_beside(const std::filesystem::path& program);

}  // namespace raystep
