#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace raystep {

/// What one scene costs the renderer, each time the best of `rounds` runs.
struct SceneCost {
    double load_seconds = 0;    ///< reading the file: what `raystep info` does
    double build_seconds = 0;   ///< prepare_render_scene: cameras, instances, every BVH
    double render_seconds = 0;  ///< the full view on the given threads
    /// Heap memory the loaded and prepared scene holds, where the C library counts it (glibc's
    /// mallinfo2); nullopt elsewhere.
    std::optional<std::size_t> memory_bytes;
};

/// Loads, prepares and renders the scene's full view `rounds` times on `threads` threads (at
/// `scale` of its width and height, for a quick run), keeping each step's best time.
SceneCost measure_scene_cost(const std::filesystem::path& scene, int threads, int rounds,
                             double scale);

/// The bars of scale, measured in one run on scenes/scale/ (docs/measurements/scale.md): a
/// thousand transformed spheres render within 1.5 times a 127,408-triangle mesh scene of the same
/// size and lights; a thousand instanced bunnies take within twice one bunny's memory and build;
/// loading the mesh scene (`raystep info`) takes at most a fifth of rendering it. Prints a table
/// and one line per bar, "met" or "MISSED": a bar is read, never a failure of the command, since
/// its times depend on the machine's load. With `quick`, one round at a quarter of each side.
void run_scale_bars(const std::filesystem::path& scenes, int threads, bool quick);

}  // namespace raystep
