#include "app/view/program_restart.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <system_error>

#if !defined(_WIN32)
#include <unistd.h>
#endif

namespace raystep {

std::filesystem::path own_program_file(const char* argv0) {
    std::error_code error;
    const std::filesystem::path linux_self = "/proc/self/exe";
    if (std::filesystem::exists(linux_self, error)) {
        const std::filesystem::path target = std::filesystem::read_symlink(linux_self, error);
        if (!error) return target;
    }
    if (argv0 == nullptr || *argv0 == '\0') return {};
    const std::filesystem::path given = argv0;
    if (given.has_parent_path()) return std::filesystem::absolute(given, error);
    const char* path = std::getenv("PATH");
    if (path == nullptr) return {};
#if defined(_WIN32)
    const char separator = ';';
#else
    const char separator = ':';
#endif
    std::string folders = path;
    std::size_t start = 0;
    while (start <= folders.size()) {
        const std::size_t end = std::min(folders.find(separator, start), folders.size());
        const std::filesystem::path candidate =
            std::filesystem::path(folders.substr(start, end - start)) / given;
        if (std::filesystem::is_regular_file(candidate, error)) return candidate;
        start = end + 1;
    }
    return {};
}

bool can_restart_program() {
#if defined(_WIN32)
    return false;
#else
    return true;
#endif
}

bool program_can_run(const std::filesystem::path& program) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(program, error)) return false;
#if defined(_WIN32)
    return true;
#else
    return ::access(program.c_str(), X_OK) == 0;
#endif
}

std::string restart_program(const std::filesystem::path& program,
                            const std::vector<std::string>& arguments) {
#if defined(_WIN32)
    (void)program;
    (void)arguments;
    return "restarting itself is not supported on Windows: start raystep view again";
#else
    std::vector<char*> argv;
    for (const std::string& argument : arguments)
        argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    ::execv(program.c_str(), argv.data());
    return std::strerror(errno);
#endif
}

}  // namespace raystep
