#pragma once

#include <cstddef>
#include <functional>

namespace raystep {

/// The chunk size a workload of `count` rays is split into, the same for every structure: about
/// 64 chunks or more, at most 1024 rays each, so that threads share the work evenly and the
/// handing out costs nothing next to the rays.
std::size_t chunk_size(std::size_t count);

/// Calls work(begin, end, worker) for each chunk [begin, end) of [0, count), `chunk` items long
/// (the last may be shorter), handed out in order to `threads` threads; `worker` in
/// [0, threads) says which thread runs it. With one thread, everything runs on the calling thread.
/// After every thread has stopped, rethrows the first exception a chunk threw (the other threads
/// take no new chunks once one has thrown).
void for_each_chunk(std::size_t count, std::size_t chunk, int threads,
                    const std::function<void(std::size_t, std::size_t, int)>& work);

}  // namespace raystep
