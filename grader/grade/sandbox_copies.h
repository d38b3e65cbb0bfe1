#pragma once

#include <cstdint>
#include <filesystem>

namespace raystep::grade {

// Copies that the grader makes for the sandbox's user to read: of the repository's headers and
// scenes, of the build's libraries, of a submission's files. Each copy gets its mode from here,
// never from its source (a private 0600 source file, or a build tree shut with chmod o-rwx, would
// otherwise hand the sandbox files it cannot read), and each is read without following a link and
// written where nothing stood before, so that a link put in the grader's way (by a submission's
// process, in a folder it may write) is refused instead of followed.

/// Copies the regular file `from` to the new file `to` with `mode`, at most `largest` bytes.
/// Throws std::runtime_error naming the file when `from` is a link or not a regular file, is
/// larger, or cannot be read, or when `to` exists.
void copy_file_for_sandbox(const std::filesystem::path& from, const std::filesystem::path& to,
                           std::filesystem::perms mode, std::uintmax_t largest = UINTMAX_MAX);

/// Copies the folder `from` into the new folder `to`: folders 0755, files 0644, links and special
/// files left out.
void copy_tree_for_sandbox(const std::filesystem::path& from, const std::filesystem::path& to);

/// Read by anyone, written by the grader: the mode of a copied file.
inline constexpr std::filesystem::perms kSharedFile =
    std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
    std::filesystem::perms::group_read | std::filesystem::perms::others_read;

/// A copied program: run by anyone.
inline constexpr std::filesystem::perms kSharedProgram =
    kSharedFile | std::filesystem::perms::owner_exec | std::filesystem::perms::group_exec |
    std::filesystem::perms::others_exec;

}  // namespace raystep::grade
