// Hostile program for the sandbox's tests: prints the file PATH (its argument), or why it cannot.
// Exits 0 when it read it, 1 when not.
#include <cerrno>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
    if (argc < 2) return 2;
    std::FILE* file = std::fopen(argv[1], "rb");
    if (!file) {
        std::printf("cannot read %s: %s\n", argv[1], std::strerror(errno));
        return 1;
    }
    char buffer[4096];
    for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, file)) > 0;) {
        std::fwrite(buffer, 1, got, stdout);
    }
    std::fclose(file);
    return 0;
}
