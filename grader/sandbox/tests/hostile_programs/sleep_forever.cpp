// Hostile program for the sandbox's tests: waits forever without using CPU, so that only the
// wall-clock limit can end it.
#include <unistd.h>

int main() {
    for (;;)
        pause();
}
