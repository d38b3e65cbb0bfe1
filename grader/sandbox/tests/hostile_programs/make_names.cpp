// Hostile program for the sandbox's tests: makes a name in /tmp by the MODE given (a file by
// open's O_CREAT, a folder, a symbolic link, an unnamed O_TMPFILE file, a socket's path), then
// opens /etc/ld.so.cache for reading, which makes nothing, and says on stdout what it did.
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "file";
    const int read_only = open("/etc/ld.so.cache", O_RDONLY | O_CLOEXEC);
    std::printf("read: %s\n", read_only >= 0 ? "yes" : "no");
    std::fflush(stdout);
    int made = -1;
    if (mode == "file") {
        made = open("/tmp/made", O_WRONLY | O_CREAT, 0600);
    } else if (mode == "folder") {
        made = mkdir("/tmp/made", 0700);
    } else if (mode == "link") {
        made = symlink("/etc/passwd", "/tmp/made");
    } else if (mode == "tmpfile") {
        made = open("/tmp", O_RDWR | O_TMPFILE, 0600);
    } else if (mode == "socket") {
        const int s = socket(AF_UNIX, SOCK_STREAM, 0);
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        std::strcpy(address.sun_path, "/tmp/made");
        made = bind(s, reinterpret_cast<const sockaddr*>(&address), sizeof address);
    }
    std::printf("made: %s\n", made >= 0 ? "yes" : "no");
    return 0;
}
