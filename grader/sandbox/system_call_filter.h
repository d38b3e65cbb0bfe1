#pragma once

#include <linux/filter.h>

#include <string>
#include <vector>

namespace raystep::grade {

/// What the kernel refuses a sandboxed program, as a seccomp filter (a classic BPF program over
/// struct seccomp_data).
///
/// Always: memory that the address-space limit does not count, which would let a run hold far
/// more than its budget for as long as it runs (SysV shared memory, message queues and semaphores,
/// POSIX message queues, memfd files, io_uring's rings). A call to one kills the program with
/// SIGSYS: a probe or a compiler has no use for any of them, and the report can then name the
/// rule it broke.
///
/// With `single_process` (a probe), also starting a process (fork, vfork, clone without
/// CLONE_THREAD) and making a name in a file system (creat, open with O_CREAT or O_TMPFILE, mkdir,
/// mknod, link, symlink, rename, bind), each of which kills the program the same way; threads
/// still start, and clone3 and openat2, whose flags a filter cannot read, answer ENOSYS, so that
/// the C library goes through clone and openat. A program that cannot start a process does all
/// its work in its own address space, and its CPU time, as the kernel accounts it at its exit, is
/// all of the run's (SandboxRun::cpu_seconds); one that makes no name holds no inode (a folder of
/// no bytes costs memory that no size limit counts).
///
/// On an architecture the filter does not know, it is empty and nothing is refused:
/// filter_architecture() says so.
std::vector<sock_filter> system_call_filter(bool single_process);

/// The architecture the filter checks ("x86_64", "aarch64"), or empty where there is none. A call
/// made through another ABI of the same machine (32-bit x86, x32) is refused.
std::string filter_architecture();

}  // namespace raystep::grade
