#include "studies/structures/ray_chunks.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace raystep {

std::size_t chunk_size(std::size_t count) {
    return std::clamp<std::size_t>(count / 64, 1, 1024);
}

void for_each_chunk(std::size_t count, std::size_t chunk, int threads,
                    const std::function<void(std::size_t, std::size_t, int)>& work) {
    if (threads <= 1) {
        for (std::size_t begin = 0; begin < count; begin += chunk) {
            work(begin, std::min(begin + chunk, count), 0);
        }
        return;
    }

    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::mutex error_mutex;
    std::exception_ptr error;
    const auto run = [&](int worker) {
        try {
            while (!failed.load()) {
                const std::size_t begin = next.fetch_add(chunk);
                if (begin >= count) return;
                work(begin, std::min(begin + chunk, count), worker);
            }
        } catch (...) {
            std::lock_guard<std::mutex> lock(error_mutex);
            if (!error) error = std::current_exception();
            failed = true;
        }
    };

    // The calling thread is worker 0, so `threads` threads run in all. A thread that cannot be
    // started (a process limit) would make the measurement a lie about the thread count, so it
    // stops the run, after the started ones are joined.
    std::vector<std::thread> pool;
    try {
        for (int worker = 1; worker < threads; ++worker)
            pool.emplace_back(run, worker);
    } catch (...) {
        failed = true;
        for (std::thread& thread : pool)
            thread.join();
        throw;
    }
    run(0);
    for (std::thread& thread : pool)
        thread.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace raystep
