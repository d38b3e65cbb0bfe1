#include "grader/sandbox/system_call_filter.h"

#include <fcntl.h>
#include <linux/audit.h>
#include <linux/seccomp.h>
#include <sched.h>
#include <sys/syscall.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>

namespace raystep::grade {

namespace {

// The architecture a call must come through: any other ABI of the machine has other call numbers,
// and a filter that read them as this one's would let the calls it refuses through.
#if defined(__x86_64__)
constexpr std::uint32_t kArchitecture = AUDIT_ARCH_X86_64;
constexpr const char* kArchitectureName = "x86_64";
#elif defined(__aarch64__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
constexpr std::uint32_t kArchitecture = AUDIT_ARCH_AARCH64;
constexpr const char* kArchitectureName = "aarch64";
#else
constexpr std::uint32_t kArchitecture = 0;
constexpr const char* kArchitectureName = "";
#endif

// Calls that make memory outside the address space: what RLIMIT_AS never sees.
constexpr long kMemoryOutsideAddressSpace[] = {
    SYS_shmget,         SYS_shmat,   SYS_shmctl,       SYS_msgget, SYS_msgsnd,
    SYS_msgrcv,         SYS_msgctl,  SYS_semget,       SYS_semop,  SYS_semtimedop,
    SYS_semctl,         SYS_mq_open, SYS_memfd_create,
#ifdef SYS_io_uring_setup
    SYS_io_uring_setup,
#endif
#ifdef SYS_memfd_secret
    SYS_memfd_secret,
#endif
};

// Calls that start a process, apart from clone, whose flags say whether it starts a thread.
constexpr long kProcessStarts[] = {
#ifdef SYS_fork
    SYS_fork,
#endif
#ifdef SYS_vfork
    SYS_vfork,
#endif
};

// Calls that make a name in a file system (a file, a folder, a device, a link, a socket's path),
// apart from open and openat, whose flags say whether they create. Even a file of no bytes holds
// an inode and a directory entry, memory that no size limit counts.
constexpr long kNameMakers[] = {
#ifdef SYS_creat
    SYS_creat,
#endif
#ifdef SYS_mkdir
    SYS_mkdir,
#endif
#ifdef SYS_mknod
    SYS_mknod,
#endif
#ifdef SYS_link
    SYS_link,
#endif
#ifdef SYS_symlink
    SYS_symlink,
#endif
#ifdef SYS_rename
    SYS_rename,
#endif
#ifdef SYS_renameat
    SYS_renameat,
#endif
    SYS_mkdirat,  SYS_mknodat, SYS_linkat, SYS_symlinkat, SYS_renameat2, SYS_bind,
};

// open's flags that create: O_CREAT, and O_TMPFILE's own bit (O_TMPFILE includes O_DIRECTORY).
constexpr std::uint32_t kCreatingFlags = O_CREAT | (O_TMPFILE & ~O_DIRECTORY);

constexpr std::uint32_t kKill = SECCOMP_RET_KILL_PROCESS;
constexpr std::uint32_t kAllow = SECCOMP_RET_ALLOW;
constexpr std::uint32_t kNoSuchCall = SECCOMP_RET_ERRNO | (ENOSYS & SECCOMP_RET_DATA);

sock_filter load_word(std::size_t offset) {
    return BPF_STMT(BPF_LD | BPF_W | BPF_ABS, static_cast<std::uint32_t>(offset));
}

sock_filter give(std::uint32_t action) {
    return BPF_STMT(BPF_RET | BPF_K, action);
}

// For the call `number` alone, the one whose word at `offset` of seccomp_data has any bit of `mask`
// set is killed (with `kill_when_set`; else the one with none set), and the other allowed: a
// block of its own, after which the accumulator still holds the call number for other calls.
void add_flag_rule(std::vector<sock_filter>& program, long number, std::size_t offset,
                   std::uint32_t mask, bool kill_when_set) {
    program.push_back(
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, static_cast<std::uint32_t>(number), 0, 4));
    program.push_back(load_word(offset));
    // Set: on to the kill, or past it to the allow; not set: the other
    const std::uint8_t to_set = kill_when_set ? 0 : 1;
    const std::uint8_t to_clear = kill_when_set ? 1 : 0;
    program.push_back(BPF_JUMP(BPF_JMP | BPF_JSET | BPF_K, mask, to_set, to_clear));
    program.push_back(give(kKill));
    program.push_back(give(kAllow));
}

// `action` when the call number in the accumulator is `number`; else on to the next instruction.
void add_call_rule(std::vector<sock_filter>& program, long number, std::uint32_t action) {
    program.push_back(
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, static_cast<std::uint32_t>(number), 0, 1));
    program.push_back(give(action));
}

}  // namespace

std::vector<sock_filter> system_call_filter(bool single_process) {
    if (kArchitecture == 0) return {};
    std::vector<sock_filter> program;

    // Another ABI of the machine: refused outright
    program.push_back(load_word(offsetof(seccomp_data, arch)));
    program.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kArchitecture, 1, 0));
    program.push_back(give(kKill));
    program.push_back(load_word(offsetof(seccomp_data, nr)));
#if defined(__x86_64__)
    // x32's calls share AUDIT_ARCH_X86_64 and are told apart by this bit of the number
    constexpr std::uint32_t kX32Bit = 0x40000000;
    program.push_back(BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, kX32Bit, 0, 1));
    program.push_back(give(kKill));
#endif

    // Memory the address-space limit does not count
    for (const long number : kMemoryOutsideAddressSpace)
        add_call_rule(program, number, kKill);

    if (single_process) {
        // No process but this one; threads through clone
        for (const long number : kProcessStarts)
            add_call_rule(program, number, kKill);
#ifdef SYS_clone3
        add_call_rule(program, SYS_clone3, kNoSuchCall);
#endif
        // No name made in any file system; openat2's flags sit in a struct no filter can read,
        // and the C library's open never uses it
        for (const long number : kNameMakers)
            add_call_rule(program, number, kKill);
#ifdef SYS_openat2
        add_call_rule(program, SYS_openat2, kNoSuchCall);
#endif

        // The calls whose flags decide. A flag word's low 32 bits, on a little-endian machine,
        // are the first word of its argument: clone's flags args[0], open's args[1], openat's
        // args[2].
        const auto argument = [](int k) { return offsetof(seccomp_data, args) + 8 * k; };
        add_flag_rule(program, SYS_clone, argument(0), CLONE_THREAD, false);
#ifdef SYS_open
        add_flag_rule(program, SYS_open, argument(1), kCreatingFlags, true);
#endif
        add_flag_rule(program, SYS_openat, argument(2), kCreatingFlags, true);
    }
    program.push_back(give(kAllow));
    return program;
}

std::string filter_architecture() {
    return kArchitectureName;
}

}  // namespace raystep::grade
