#include "grader/sandbox/system_call_filter.h"

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

constexpr std::uint32_t kKill = SECCOMP_RET_KILL_PROCESS;
constexpr std::uint32_t kAllow = SECCOMP_RET_ALLOW;

sock_filter load_word(std::size_t offset) {
    return BPF_STMT(BPF_LD | BPF_W | BPF_ABS, static_cast<std::uint32_t>(offset));
}

sock_filter give(std::uint32_t action) {
    return BPF_STMT(BPF_RET | BPF_K, action);
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
        add_call_rule(program, SYS_clone3, SECCOMP_RET_ERRNO | (ENOSYS & SECCOMP_RET_DATA));
#endif
        // clone's flags are its first argument; their low 32 bits, on a little-endian machine,
        // are the first word of args[0]. Not clone: on to allow; clone with CLONE_THREAD: allow.
        program.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, SYS_clone, 0, 3));
        program.push_back(load_word(offsetof(seccomp_data, args)));
        program.push_back(BPF_JUMP(BPF_JMP | BPF_JSET | BPF_K, CLONE_THREAD, 1, 0));
        program.push_back(give(kKill));
    }
    program.push_back(give(kAllow));
    return program;
}

std::string filter_architecture() {
    return kArchitectureName;
}

}  // namespace raystep::grade
