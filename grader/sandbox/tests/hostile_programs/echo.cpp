// Program for the sandbox's tests, the well-behaved one: copies stdin to stdout, byte for byte.
#include <unistd.h>

#include <vector>

int main() {
    std::vector<char> buffer(std::size_t{64} << 10);
    for (;;) {
        const ssize_t got = read(0, buffer.data(), buffer.size());
        if (got == 0) return 0;
        if (got < 0) return 1;
        for (ssize_t done = 0; done < got;) {
            const ssize_t put =
                write(1, buffer.data() + done, static_cast<std::size_t>(got - done));
            if (put < 0) return 1;
            done += put;
        }
    }
}
