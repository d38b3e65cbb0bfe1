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

WorkFolder::WorkFolder(const fs::path& parent, bool keep) : keep_(keep) {
    const fs::path base = absolute_normal(parent);
    std::error_code error;
    fs::create_directories(base, error);
    std::string name = (base / "work-XXXXXX").string();
    if (mkdtemp(name.data()) == nullptr) {
        throw std::runtime_error("cannot make a work folder in " + base.string() + ": " +
                                 std::strerror(errno));
    }
    path_ = name;
    // Searchable, not listable: the sandbox's user reaches the folders it is shown by name.
    fs::permissions(path_, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
    if (geteuid() == 0) {
        if (const std::optional<fs::path> shut = shut_to_others(path_)) {
            fs::remove_all(path_, error);
            throw std::runtime_error(
                "the work folder " + path_.string() + " lies under " + shut->string() +
                ", which others may not search: the sandbox's user (nobody) could not reach the "
                "probes. Give --work a folder under one that all may search, such as /tmp");
        }
    }
}

WorkFolder::~WorkFolder() {
    if (keep_ || path_.empty()) return;
    std::error_code ignored;
    fs::remove_all(path_, ignored);
}

fs::path work_parent_for(const fs::path& output) {
    const fs::path folder = absolute_normal(output);
    if (geteuid() != 0 || !shut_to_others(folder)) return folder;
    const char* tmpdir = std::getenv("TMPDIR");
    return tmpdir && *tmpdir ? fs::path(tmpdir) / "raystep-grade" : fs::path("/tmp/raystep-grade");
}

}  // namespace raystep::grade
