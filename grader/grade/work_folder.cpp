#include "grader/grade/work_folder.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include "grader/sandbox/sandbox_paths.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

// The first folder from the root down to `folder` that others may not search, or nothing.
std::optional<fs::path> shut_to_others(const fs::path& folder) {
    fs::path path;
    for (const fs::path& part : folder) {
        path /= part;
        struct stat status {};
        if (stat(path.c_str(), &status) != 0 || (status.st_mode & S_IXOTH) == 0) return path;
    }
    return std::nullopt;
}

}  // namespace

WorkFolder::WorkFolder(const fs::path& parent, const std::string& prefix, bool keep) : keep_(keep) {
    const fs::path base = absolute_normal(parent);
    std::string name = (base / (prefix + "XXXXXX")).string();
    if (mkdtemp(name.data()) == nullptr) {
        throw std::runtime_error("cannot make a work folder in " + base.string() + ": " +
                                 std::strerror(errno));
    }
    path_ = name;
    // Searchable, not listable: the sandbox's user reaches the folders it is shown by name.
    fs::permissions(path_, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
    if (geteuid() == 0) {
        if (const std::optional<fs::path> shut = shut_to_others(path_)) {
            std::error_code error;
            fs::remove_all(path_, error);
            throw std::runtime_error(
                "the work folder " + path_.string() + " lies under " + shut->string() +
                ", which others may not search: the sandbox's user (nobody) could not reach the "
                "probes. Give --work a folder under one that all may search, such as /tmp");
        }
    }
}

WorkFolder::WorkFolder(WorkFolder&& other) noexcept
    : path_(std::move(other.path_)), keep_(other.keep_) {
    other.path_.clear();
}

WorkFolder::~WorkFolder() {
    if (keep_ || path_.empty()) return;
    std::error_code ignored;
    fs::remove_all(path_, ignored);
}

WorkFolder make_work_folder(const fs::path& output, const fs::path& chosen, bool keep) {
    if (!chosen.empty()) return WorkFolder(chosen, "work-", keep);
    const fs::path folder = absolute_normal(output);
    if (geteuid() != 0 || !shut_to_others(folder)) return WorkFolder(folder, "work-", keep);
    // Straight in the temporary folder, never in a folder of ours there: another user could make
    // that folder first, and swap what we make in it for links of theirs. mkdtemp's folder is
    // ours alone, and /tmp's sticky bit keeps others from moving it.
    const char* tmpdir = std::getenv("TMPDIR");
    return WorkFolder(tmpdir && *tmpdir ? fs::path(tmpdir) : fs::path("/tmp"),
                      "raystep-grade-work-", keep);
}

}  // namespace raystep::grade
