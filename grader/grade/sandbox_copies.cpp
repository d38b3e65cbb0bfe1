#include "grader/grade/sandbox_copies.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

// A descriptor closed at the end of its scope.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) close(fd);
    }
};

[[noreturn]] void fail(const fs::path& path, const std::string& what) {
    throw std::runtime_error(path.string() + ": " + what);
}

}  // namespace

void copy_file_for_sandbox(const fs::path& from, const fs::path& to, fs::perms mode,
                           std::uintmax_t largest) {
    const Descriptor in{open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK)};
    if (in.fd < 0) fail(from, std::string("cannot be read: ") + std::strerror(errno));
    struct stat status {};
    if (fstat(in.fd, &status) != 0 || !S_ISREG(status.st_mode)) fail(from, "not a regular file");
    if (static_cast<std::uintmax_t>(status.st_size) > largest) fail(from, "larger than it may be");
    const Descriptor out{
        open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600)};
    if (out.fd < 0) fail(to, std::string("cannot be made: ") + std::strerror(errno));
    std::vector<char> buffer(std::size_t{64} << 10);
    std::uintmax_t copied = 0;
    for (;;) {
        const ssize_t got = read(in.fd, buffer.data(), buffer.size());
        if (got == 0) break;
        if (got < 0) fail(from, std::string("cannot be read: ") + std::strerror(errno));
        copied += static_cast<std::uintmax_t>(got);
        if (copied > largest) fail(from, "larger than it may be");
        for (ssize_t done = 0; done < got;) {
            const ssize_t put =
                write(out.fd, buffer.data() + done, static_cast<std::size_t>(got - done));
            if (put < 0) fail(to, std::string("cannot be written: ") + std::strerror(errno));
            done += put;
        }
    }
    if (fchmod(out.fd, static_cast<mode_t>(mode)) != 0) {
        fail(to, std::string("cannot be given its mode: ") + std::strerror(errno));
    }
}

void copy_tree_for_sandbox(const fs::path& from, const fs::path& to) {
    fs::create_directory(to);
    fs::permissions(to, kSharedProgram);
    for (const fs::directory_entry& entry : fs::directory_iterator(from)) {
        const fs::file_status status = entry.symlink_status();
        const fs::path target = to / entry.path().filename();
        if (fs::is_directory(status)) {
            copy_tree_for_sandbox(entry.path(), target);
        } else if (fs::is_regular_file(status)) {
            copy_file_for_sandbox(entry.path(), target, kSharedFile);
        }
    }
}

}  // namespace raystep::grade
