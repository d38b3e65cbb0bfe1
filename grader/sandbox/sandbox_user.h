#pragma once

#include <sys/resource.h>
#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <vector>

#include "grader/sandbox/child_process.h"

namespace raystep::grade {

/// The uid and gid a sandboxed program has inside bubblewrap: the kernel's overflow user,
/// "nobody".
inline constexpr uid_t kSandboxUid = 65534;
inline constexpr gid_t kSandboxGid = 65534;

/// Who the program of one run is, outside bubblewrap's namespace or without one. When the grader
/// is root: a user of the run's own, a uid and gid that no process has, drawn from a range far
/// above any real user's (kRunUsers), so that nothing one run leaves behind (a process that left
/// its session, a file it owns) can reach another run, and the process limit that holds a fork
/// bomb is the run's alone. Else nullopt: the grader's own user, which it cannot leave. Never
/// root: the kernel exempts uid 0 from RLIMIT_NPROC, outside bubblewrap a root program could do
/// anything, and inside it (mapped to root) the files it makes in the writable folder would be
/// root's on the host, set-uid ones included.
std::optional<Identity> program_identity();

/// The uids (and gids) program_identity draws from: 2^24 of them from 0x60000000, above the
/// ranges that systems, LDAP and container subordinate ids hand out.
inline constexpr uid_t kRunUsersFirst = 0x60000000;
inline constexpr uid_t kRunUsersCount = 1u << 24;

/// Ends every process that runs as `identity`'s uid, by a child that becomes that user and sends
/// SIGKILL to all it may signal: what a run left behind outside bubblewrap, which would otherwise
/// outlive it.
void end_processes_of(const Identity& identity);

/// The tasks (processes and threads: RLIMIT_NPROC counts both) that run as real uid `uid` now,
/// counted in /proc; 0 where there is no /proc.
rlim_t tasks_of(uid_t uid);

/// Makes `folder` writable by `identity`: gives it the folder itself, not what is in it, so that
/// the program can add and remove files there but cannot touch another owner's file in place.
/// Throws std::runtime_error when it cannot.
void hand_over(const std::filesystem::path& folder, const Identity& identity);

/// Those of `paths` that a sandboxed program could read or execute (or, for a folder, list or
/// enter), were it to name them: asked of the kernel by a child process that becomes a user of
/// program_identity's. Empty when the grader is not root (its programs then run as its own user,
/// and only bubblewrap can hide anything).
std::vector<std::filesystem::path> open_to_sandbox_user(
    const std::vector<std::filesystem::path>& paths);

/// Gives `path` (not what is in it) back to the grader's own user after a program that ran as
/// another made it or was handed it. Does nothing when the grader is not root (no program could
/// have run as another user). Throws std::runtime_error when it cannot.
void reclaim(const std::filesystem::path& path);

}  // namespace raystep::grade
