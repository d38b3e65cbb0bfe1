#pragma once

#include <filesystem>
#include <string>

namespace raystep::grade {

/// The PATH a sandboxed program gets, and the one its name is looked up in: the system's folders
/// only, which the sandbox shows read-only. Never the grader's PATH, which may name the
/// instructor's own folders.
inline constexpr char kSandboxPath[] = "/usr/local/bin:/usr/bin:/bin";

/// `name` as an absolute path: looked up in kSandboxPath when it has no slash, else taken from
/// the current folder. Throws std::runtime_error when that is not an executable file.
std::filesystem::path find_executable(const std::string& name);

/// `path` made absolute from the current folder, without "." and "..", and without a trailing
/// slash: the form in which paths are compared and handed to bubblewrap.
std::filesystem::path absolute_normal(const std::filesystem::path& path);

/// True when `path` is `folder` or lies under it; both absolute_normal.
bool is_within(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace raystep::grade
