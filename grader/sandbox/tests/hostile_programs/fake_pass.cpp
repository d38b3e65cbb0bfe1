// Hostile program for the sandbox's tests: claims success the way a test runner would, and exits 0
// at once, before any of the work it was asked to do. The sandbox must report just that.
#include <cstdio>
#include <cstdlib>

int main() {
    std::printf(
        "===============================================================================\n");
    std::printf("All tests passed (42 assertions in 7 test cases)\n");
    std::fflush(stdout);
    std::exit(0);
}
