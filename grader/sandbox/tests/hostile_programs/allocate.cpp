// Hostile program for the sandbox's tests: allocates and touches memory 16 MiB at a time, without
// end, printing how much it holds after each step. The address-space limit stops it: new throws
// std::bad_alloc, which ends it with SIGABRT.
#include <cstdio>
#include <memory>
#include <vector>

int main() {
    constexpr std::size_t kStep = std::size_t{16} << 20;
    std::vector<std::unique_ptr<char[]>> held;
    for (;;) {
        held.emplace_back(new char[kStep]);
        // Touch every page, through volatile so that no store is optimized away.
        volatile char* bytes = held.back().get();
        for (std::size_t k = 0; k < kStep; k += 4096)
            bytes[k] = 1;
        std::printf("%zu MiB\n", held.size() * 16);
        std::fflush(stdout);
    }
}
