// Hostile program for the sandbox's tests: writes to a page it may not touch, and dies of SIGSEGV.
#include <sys/mman.h>

int main() {
    void* page = mmap(nullptr, 4096, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (page == MAP_FAILED) return 2;
    *static_cast<volatile char*>(page) = 1;
    return 0;
}
