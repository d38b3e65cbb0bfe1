// Program for the sandbox's tests of the answer channel: prints one line on stdout, as a student's
// debugging would, and writes one on descriptor 3 when that is open; says on stdout when not.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>

int main() {
    std::printf("printed on stdout\n");
    std::fflush(stdout);
    if (fcntl(3, F_GETFD) < 0) {
        std::printf("no descriptor 3\n");
        return 0;
    }
    const char answer[] = "written on descriptor 3\n";
    return write(3, answer, std::strlen(answer)) == static_cast<ssize_t>(std::strlen(answer)) ? 0
                                                                                              : 1;
}
