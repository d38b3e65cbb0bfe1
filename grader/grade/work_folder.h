#pragma once

#include <filesystem>

namespace raystep::grade {

/// The folder one grade builds in (the submission's files, headers, objects, probes), made fresh
/// for it and removed with it. The sandbox's user must reach it, while the reports may go
/// anywhere the instructor can write, a private home folder included: work_parent_for chooses.
class WorkFolder {
  public:
    /// Makes PARENT/work-XXXXXX, searchable but not listable by others. Throws
    /// std::runtime_error naming the folder when it cannot, or when a folder above it is shut to
    /// others while the grader is root (the sandbox's user could not reach the probes).
    WorkFolder(const std::filesystem::path& parent, bool keep);
    /// Removes the folder and everything in it, unless it is kept.
    ~WorkFolder();
    WorkFolder(const WorkFolder&) = delete;
    WorkFolder& operator=(const WorkFolder&) = delete;

    const std::filesystem::path& path() const { return path_; }
    bool kept() const { return keep_; }

  private:
    std::filesystem::path path_;
    bool keep_ = false;
};

/// Where a grade writing its reports to `output` builds, unless the instructor says: `output`
/// itself, where the sandbox's user can reach it (always, when the grader is not root: the
/// sandbox then runs as the grader's own user); else the system's temporary folder ($TMPDIR, else
/// /tmp), as when the reports go under a private (0700) home folder.
std::filesystem::path work_parent_for(const std::filesystem::path& output);

}  // namespace raystep::grade
