#pragma once

#include <algorithm>
#include <chrono>
#include <limits>

namespace raystep {

/// Seconds of wall time that fn() takes, by std::chrono::steady_clock.
template <class Function>
double seconds_of(Function&& fn) {
    const auto start = std::chrono::steady_clock::now();
    fn();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The least of `runs` timings of fn(): the run the rest of the machine disturbed least.
template <class Function>
double best_of(int runs, Function&& fn) {
    double best = std::numeric_limits<double>::infinity();
    for (int run = 0; run < runs; ++run)
        best = std::min(best, seconds_of(fn));
    return best;
}

}  // namespace raystep
