// Program for the sandbox's tests: three threads, each spinning for 0.3 s of its own CPU time,
// so that the run costs about 0.9 s of CPU time whatever the machine's cores.
#include <ctime>
#include <thread>
#include <vector>

namespace {

double thread_seconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void spin() {
    const double start = thread_seconds();
    volatile double sink = 0.0;
    while (thread_seconds() - start < 0.3)
        sink = sink + 1.0;
}

}  // namespace

int main() {
    std::vector<std::thread> threads;
    for (int k = 0; k < 3; ++k)
        threads.emplace_back(spin);
    for (std::thread& thread : threads)
        thread.join();
    return 0;
}
