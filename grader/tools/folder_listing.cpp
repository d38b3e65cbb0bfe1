#include "grader/tools/folder_listing.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deque>
#include <vector>

#include "grader/tools/unpacked_entry.h"

namespace raystep::grade {

namespace {

// A submission is a few dozen files: past this many entries, a folder is not looked through
// further.
constexpr long kMostListedEntries = 20000;

// Folders nested deeper than this are listed but not entered: a student's files sit three deep
// (stages/<stage>/<file>), under a few folders of a repository at most.
constexpr std::size_t kDeepestFolder = 16;

// Folders that hold what tools made, never a student's sources: a working copy's history, build
// products, packages. Listed, not looked into, so that their thousands of entries cannot crowd
// the cap above.
bool made_by_tools(const std::string& name) {
    static const char* const names[] = {".git",
                                        ".hg",
                                        ".svn",
                                        "build",
                                        "cmake-build-debug",
                                        "cmake-build-release",
                                        "out",
                                        "target",
                                        "node_modules",
                                        ".venv",
                                        "venv",
                                        "__pycache__",
                                        ".cache",
                                        ".vs"};
    return std::any_of(std::begin(names), std::end(names),
                       [&](const char* tool_folder) { return name == tool_folder; });
}

std::string joined(const std::vector<std::string>& components) {
    std::string path;
    for (const std::string& component : components)
        path += (path.empty() ? "" : "/") + component;
    return path;
}

// The folder at `components` under `root`, opened one component at a time from its parent's
// descriptor with O_NOFOLLOW: a link anywhere on the way fails the open (ELOOP, or ENOTDIR), so
// that a link swapped in after it was listed is not followed either. -1 with errno on failure.
int open_folder(int root, const std::vector<std::string>& components) {
    int folder = fcntl(root, F_DUPFD_CLOEXEC, 0);
    for (const std::string& name : components) {
        if (folder < 0) return -1;
        const int next =
            openat(folder, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        const int error = errno;
        close(folder);
        errno = error;
        folder = next;
    }
    return folder;
}

// The names in the folder open at `folder`, sorted: readdir gives them in the file system's order,
// and a listing should not depend on it.
std::vector<std::string> names_in(int folder) {
    std::vector<std::string> names;
    const int copy = fcntl(folder, F_DUPFD_CLOEXEC, 0);
    DIR* listing = copy >= 0 ? fdopendir(copy) : nullptr;
    if (!listing) {
        if (copy >= 0) close(copy);
        return names;
    }
    while (const dirent* entry = readdir(listing)) {
        const std::string name = entry->d_name;
        if (name != "." && name != "..") names.push_back(name);
    }
    closedir(listing);
    std::sort(names.begin(), names.end());
    return names;
}

// What the link `name` in `folder` holds, read and never followed.
std::string link_target(int folder, const std::string& name) {
    char target[4096];
    const ssize_t length = readlinkat(folder, name.c_str(), target, sizeof target);
    return length < 0 ? "" : std::string(target, static_cast<std::size_t>(length));
}

// Copies the file `name` of `folder`, as it was listed (`listed`), to the new file `into`, at
// most `limit` bytes. Opened without following a link, and checked to be the very file listed
// (the same device and inode, still a regular file), so that nothing swapped in between the
// listing and the copy is read. False when it cannot be, or is longer than `limit`.
bool copy_file(int folder, const std::string& name, const struct stat& listed,
               const std::string& into, long long limit) {
    const int in =
        openat(folder, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (in < 0) return false;
    struct stat opened {};
    if (fstat(in, &opened) != 0 || !S_ISREG(opened.st_mode) || opened.st_dev != listed.st_dev ||
        opened.st_ino != listed.st_ino) {
        close(in);
        return false;
    }
    const int out = open(into.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (out < 0) {
        close(in);
        return false;
    }
    long long copied = 0;
    char buffer[65536];
    bool ok = true;
    for (;;) {
        const ssize_t got = read(in, buffer, sizeof buffer);
        if (got == 0) break;
        if (got < 0 || copied + got > limit ||
            write(out, buffer, static_cast<std::size_t>(got)) != got) {
            ok = false;
            break;
        }
        copied += got;
    }
    close(in);
    ok = close(out) == 0 && ok;
    if (!ok) unlink(into.c_str());
    return ok;
}

}  // namespace

int list_folder(int root, const FolderTake& take) {
    std::deque<std::vector<std::string>> folders{{}};
    long index = 0;
    long long taken_bytes = 0;
    while (!folders.empty()) {
        const std::vector<std::string> components = std::move(folders.front());
        folders.pop_front();
        const int folder = open_folder(root, components);
        if (folder < 0) {
            const int error = errno;
            std::fprintf(stderr, "the folder %s could not be opened: %s%s\n",
                         components.empty() ? "itself" : joined(components).c_str(),
                         std::strerror(error),
                         error == EACCES ? " (the grader reads a submission as a user of its own: "
                                           "make it readable by others, chmod -R go+rX)"
                                         : "");
            return 4;
        }
        for (const std::string& name : names_in(folder)) {
            if (index >= kMostListedEntries) {
                std::fprintf(stderr, "the folder was cut after %ld entries\n", index);
                close(folder);
                return 4;
            }
            std::vector<std::string> path = components;
            path.push_back(name);
            const std::string shown = joined(path);
            const std::string file = take.into + "/" + std::to_string(index);
            ++index;

            // The entry itself, never what a link points to
            struct stat listed {};
            if (fstatat(folder, name.c_str(), &listed, AT_SYMLINK_NOFOLLOW) != 0) {
                print_entry(shown, "other", -1, false);
            } else if (S_ISLNK(listed.st_mode)) {
                print_entry(shown, "link", 0, false, link_target(folder, name));
            } else if (S_ISDIR(listed.st_mode)) {
                print_entry(shown, "folder", 0, false);
                if (!made_by_tools(name) && path.size() < kDeepestFolder) {
                    folders.push_back(std::move(path));
                }
            } else if (S_ISREG(listed.st_mode) && listed.st_nlink > 1) {
                print_entry(shown, "link", listed.st_size, false,
                            "(a hard link: another name of a file that may lie anywhere)");
            } else if (S_ISREG(listed.st_mode)) {
                const long long size = listed.st_size;
                const bool taken = take.wanted.count(name) > 0 && size <= take.largest_file &&
                                   taken_bytes + size <= take.total &&
                                   copy_file(folder, name, listed, file, take.largest_file);
                if (taken) taken_bytes += size;
                print_entry(shown, "file", size, taken);
            } else {
                print_entry(shown, "other", -1, false);
            }
        }
        close(folder);
    }
    return 0;
}

}  // namespace raystep::grade
