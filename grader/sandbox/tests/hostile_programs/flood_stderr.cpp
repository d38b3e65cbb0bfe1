// Hostile program for the sandbox's tests: writes to stderr without end.
#include <unistd.h>

#include <vector>

int main() {
    const std::vector<char> block(std::size_t{64} << 10, 'e');
    for (;;) {
        if (write(2, block.data(), block.size()) < 0) return 1;
    }
}
