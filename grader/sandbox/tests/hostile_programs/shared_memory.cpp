// Hostile program for the sandbox's tests: holds memory outside its address space, 64 MiB at a
// time up to 3 GiB, which RLIMIT_AS never counts: SysV shared memory segments attached, touched
// and detached ("sysv"), memfd files ("memfd"), or a POSIX message queue ("mqueue"). Prints how
// much it holds after each step; the sandbox's system call filter stops it at the first call.
#include <fcntl.h>
#include <mqueue.h>
#include <sys/ipc.h>
#include <sys/mman.h>
#include <sys/shm.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>

namespace {

constexpr std::size_t kStep = std::size_t{64} << 20;
constexpr int kSteps = 48;  // 3 GiB

void touch(void* memory) {
    volatile char* bytes = static_cast<char*>(memory);
    for (std::size_t k = 0; k < kStep; k += 4096)
        bytes[k] = 1;
}

bool hold_sysv() {
    const int segment = shmget(IPC_PRIVATE, kStep, IPC_CREAT | 0600);
    if (segment < 0) return false;
    void* memory = shmat(segment, nullptr, 0);
    if (memory == reinterpret_cast<void*>(-1)) return false;
    touch(memory);
    return shmdt(memory) == 0;
}

bool hold_memfd() {
    const int file = memfd_create("held", 0);
    if (file < 0 || ftruncate(file, kStep) != 0) return false;
    void* memory = mmap(nullptr, kStep, PROT_READ | PROT_WRITE, MAP_SHARED, file, 0);
    if (memory == MAP_FAILED) return false;
    touch(memory);
    return munmap(memory, kStep) == 0;  // the file stays open, and its pages held
}

bool hold_mqueue() {
    return mq_open("/raystep-held", O_CREAT | O_RDWR, 0600, nullptr) != static_cast<mqd_t>(-1);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "sysv";
    for (int step = 1; step <= kSteps; ++step) {
        const bool held = mode == "memfd"    ? hold_memfd()
                          : mode == "mqueue" ? hold_mqueue()
                                             : hold_sysv();
        if (!held) {
            std::printf("refused after %d MiB: %s\n", (step - 1) * 64, std::strerror(errno));
            return 1;
        }
        std::printf("%d MiB\n", step * 64);
        std::fflush(stdout);
    }
    return 0;
}
