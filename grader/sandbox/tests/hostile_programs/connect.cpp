// Hostile program for the sandbox's tests: opens a TCP connection to ADDRESS PORT (its arguments,
// an IPv4 address), waiting at most 2 seconds, and says whether it could. Exits 0 when connected,
// 1 when not.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

int refused(const char* step, int error) {
    std::printf("cannot connect: %s: %s\n", step, std::strerror(error));
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) return 2;
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(std::atoi(argv[2])));
    if (inet_pton(AF_INET, argv[1], &address.sin_addr) != 1) return 2;

    const int fd = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
    if (fd < 0) return refused("socket", errno);
    if (connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
        if (errno != EINPROGRESS) return refused("connect", errno);
        pollfd wait{fd, POLLOUT, 0};
        if (poll(&wait, 1, 2000) != 1) return refused("connect", ETIMEDOUT);
        int error = 0;
        socklen_t size = sizeof error;
        getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &size);
        if (error != 0) return refused("connect", error);
    }
    std::printf("connected\n");
    close(fd);
    return 0;
}
