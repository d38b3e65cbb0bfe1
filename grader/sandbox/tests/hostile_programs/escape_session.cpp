// Hostile program for the sandbox's tests: starts a child that leaves the process group for a
// session of its own (out of reach of a kill of the group) and waits forever, then exits 0.
#include <unistd.h>

#include <cstdio>

int main() {
    const pid_t pid = fork();
    if (pid < 0) return 1;
    if (pid == 0) {
        setsid();
        for (;;)
            pause();
    }
    std::printf("left %d behind\n", static_cast<int>(pid));
    return 0;
}
