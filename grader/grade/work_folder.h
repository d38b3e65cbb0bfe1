#pragma once

#include <filesystem>
#include <string>

namespace raystep::grade {

/// The folder one grade builds in (the submission's files, headers, objects, probes), made fresh
/// for it and removed with it. The sandbox's user must reach it, while the reports may go
/// anywhere the instructor can write, a private home folder included: make_work_folder chooses.
class WorkFolder {
  public:
    /// Makes PARENT/PREFIXXXXXXX with mkdtemp, searchable but not listable by others. Throws
    /// std::runtime_error naming the folder when it cannot, or when a folder above it is shut to
    /// others while the grader is root (the sandbox's user could not reach the probes).
    WorkFolder(const std::filesystem::path& parent, const std::string& prefix, bool keep);
    /// Removes the folder and everything in it, unless it is kept.
    ~WorkFolder();
    WorkFolder(WorkFolder&& other) noexcept;
    WorkFolder(const WorkFolder&) = delete;
    WorkFolder& operator=(const WorkFolder&) = delete;
    WorkFolder& operator=(WorkFolder&&) = delete;

    const std::filesystem::path& path() const { return path_; }
    bool kept() const { return keep_; }

  private:
    std::filesystem::path path_;
    bool keep_ = false;
};

/// The work folder of a grade writing its reports to `output`: in `chosen` when the instructor
/// named one (--work); else beside the reports (OUT/work-XXXXXX) where the sandbox's user can
/// reach them (always, when the grader is not root: the sandbox then runs as the grader's own
/// user); else straight in the system's temporary folder ($TMPDIR, else /tmp), as when the
/// reports go under a private (0700) home folder.
WorkFolder make_work_folder(const std::filesystem::path& output,
                            const std::filesystem::path& chosen, bool keep);

}  // namespace raystep::grade
