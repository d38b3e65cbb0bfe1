#include "grader/sandbox/sandbox_paths.h"

#include <unistd.h>

#include <sstream>
#include <stdexcept>
#include <system_error>

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

bool is_executable_file(const fs::path& path) {
    std::error_code error;
    return fs::is_regular_file(path, error) && access(path.c_str(), X_OK) == 0;
}

}  // namespace

fs::path find_executable(const std::string& name) {
    if (name.empty()) throw std::runtime_error("sandbox: no program to run");
    if (name.find('/') != std::string::npos) {
        const fs::path path = absolute_normal(name);
        if (!is_executable_file(path)) {
            throw std::runtime_error("sandbox: cannot start " + path.string() +
                                     ": not an executable file");
        }
        return path;
    }
    std::istringstream folders(kSandboxPath);
    for (std::string folder; std::getline(folders, folder, ':');) {
        const fs::path path = fs::path(folder) / name;
        if (is_executable_file(path)) return path;
    }
    throw std::runtime_error("sandbox: cannot start " + name + ": not found in " + kSandboxPath);
}

fs::path absolute_normal(const fs::path& path) {
    fs::path normal = fs::absolute(path).lexically_normal();
    if (!normal.has_filename() && normal != normal.root_path()) normal = normal.parent_path();
    return normal;
}

bool is_within(const fs::path& path, const fs::path& folder) {
    auto step = path.begin();
    for (const fs::path& part : folder) {
        if (step == path.end() || *step != part) return false;
        ++step;
    }
    return true;
}

}  // namespace raystep::grade
