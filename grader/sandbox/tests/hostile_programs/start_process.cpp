// Hostile program for the sandbox's tests: starts a process (fork), which prints a line and
// exits, and waits for it. A single-process run's filter ends it at the fork with SIGSYS.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

int main() {
    const pid_t child = fork();
    if (child == 0) {
        std::printf("child started\n");
        return 0;
    }
    if (child < 0) return 1;
    int status = 0;
    waitpid(child, &status, 0);
    std::printf("parent waited\n");
    return 0;
}
