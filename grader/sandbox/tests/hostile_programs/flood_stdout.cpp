// Hostile program for the sandbox's tests: writes MIB (its argument) mebibytes of 'x' to stdout,
// then exits 0. A sandbox that stops reading at its output cap would block it, and one that
// closes the pipe would kill it with SIGPIPE.
#include <unistd.h>

#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
    const long mebibytes = argc > 1 ? std::atol(argv[1]) : 0;
    const std::vector<char> block(std::size_t{1} << 20, 'x');
    for (long k = 0; k < mebibytes; ++k) {
        for (std::size_t done = 0; done < block.size();) {
            const ssize_t put = write(1, block.data() + done, block.size() - done);
            if (put < 0) return 1;
            done += static_cast<std::size_t>(put);
        }
    }
    return 0;
}
