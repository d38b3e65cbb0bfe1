// Hostile program for the sandbox's tests: forks until the kernel refuses (at most 2,000 times, so
// that a sandbox that fails to stop it does not take the machine down), each child waiting
// forever; prints how many it made, and exits, leaving them all behind.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

int main() {
    int made = 0;
    int error = 0;
    for (; made < 2000; ++made) {
        const pid_t pid = fork();
        if (pid < 0) {
            error = errno;
            break;
        }
        if (pid == 0) {
            for (;;)
                pause();
        }
    }
    std::printf("made %d: %s\n", made, error ? std::strerror(error) : "no refusal");
    return 0;
}
