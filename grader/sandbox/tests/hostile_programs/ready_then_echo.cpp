// Program for the sandbox's tests of a delayed stdin: says on stdout whether anything waits on
// stdin within 200 ms, writes a first line on descriptor 3 (as a probe's main says it is ready),
// then copies stdin to stdout.
#include <poll.h>
#include <unistd.h>

#include <cstdio>

int main() {
    pollfd input{STDIN_FILENO, POLLIN, 0};
    const bool waiting = poll(&input, 1, 200) > 0;
    std::printf("waiting before ready: %s\n", waiting ? "yes" : "no");
    std::fflush(stdout);
    if (write(3, "ready\n", 6) != 6) return 1;
    char buffer[4096];
    for (ssize_t got; (got = read(STDIN_FILENO, buffer, sizeof buffer)) > 0;)
        std::fwrite(buffer, 1, static_cast<std::size_t>(got), stdout);
    return 0;
}
