// Hostile program for the sandbox's tests: never reads stdin; waits 200 ms, so that a sandbox
// writing a large input finds the pipe full, then says so and exits 0.
#include <unistd.h>

#include <cstdio>

int main() {
    usleep(200000);
    std::printf("ignored stdin\n");
    return 0;
}
