// Hostile program for the sandbox's tests: burns CPU without end. With --ignore-sigxcpu it ignores
// the signal of the soft CPU limit, so that only the hard one (SIGKILL) can stop it.
#include <csignal>
#include <cstring>

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "--ignore-sigxcpu") == 0) std::signal(SIGXCPU, SIG_IGN);
    volatile unsigned long turns = 0;
    for (;;)
        turns = turns + 1;
}
