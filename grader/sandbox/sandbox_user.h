#pragma once

#include <sys/resource.h>
#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <vector>

#include "grader/sandbox/child_process.h"

namespace raystep::grade {

/// The uid and gid a sandboxed program has inside bubblewrap, and outside it too when the grader
/// runs as root: the kernel's overflow user, "nobody".
inline constexpr uid_t kSandboxUid = 65534;
inline constexpr gid_t kSandboxGid = 65534;

/// Who the program runs as: nobody when the grader is root, else the grader's own user (which it
/// cannot leave). Never root: the kernel exempts uid 0 from RLIMIT_NPROC, outside bubblewrap a
/// root program could do anything, and inside it (mapped to root) the files it makes in the
/// writable folder would be root's on the host, set-uid ones included.
std::optional<Identity> program_identity();

/// The tasks (processes and threads: RLIMIT_NPROC counts both) that run as real uid `uid` now,
/// counted in /proc; 0 where there is no /proc.
rlim_t tasks_of(uid_t uid);

/// Makes `folder` writable by `identity`: gives it the folder itself, not what is in it, so that
/// the program can add and remove files there but cannot touch another owner's file in place.
/// Throws std::runtime_error when it cannot.
void hand_over(const std::filesystem::path& folder, const Identity& identity);

/// Those of `paths` that the sandbox's user could read or execute, were a program of its to name
/// them: asked of the kernel by a child process that becomes that user. Empty when the grader is
/// not root (its programs then run as its own user, and only bubblewrap can hide anything).
std::vector<std::filesystem::path> open_to_sandbox_user(
    const std::vector<std::filesystem::path>& paths);

/// Gives `path` (not what is in it) back to the grader's own user after a program that ran as
/// another made it or was handed it. Does nothing when the grader is not root (no program could
/// have run as another user). Throws std::runtime_error when it cannot.
void reclaim(const std::filesystem::path& path);

}  // namespace raystep::grade
