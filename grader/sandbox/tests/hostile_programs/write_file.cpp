// Hostile program for the sandbox's tests: writes TEXT to PATH (its arguments), and says whether
// it could. Exits 0 when it wrote, 1 when not.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
    if (argc < 3) return 2;
    const int fd = open(argv[1], O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const std::size_t size = std::strlen(argv[2]);
    if (fd < 0 || write(fd, argv[2], size) != static_cast<ssize_t>(size) || close(fd) != 0) {
        std::printf("cannot write %s: %s\n", argv[1], std::strerror(errno));
        return 1;
    }
    std::printf("wrote %s\n", argv[1]);
    return 0;
}
