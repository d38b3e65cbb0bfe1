#include "studies/scale/scene_scale.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include "base/scene/scene_loader.h"
#include "renderer/render_scene.h"
#include "renderer/tile_renderer.h"
#include "studies/common/markdown_table.h"
#include "studies/common/number_text.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace raystep {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Bytes allocated and not yet freed, small blocks and mapped ones. Not the resident size: freed
// memory stays resident for reuse, so a scene measured after another would seem to cost nothing.
// glibc only: the studies are the instructor's, and elsewhere the memory column says it was not
// measured. Under another allocator (a sanitizer's) glibc counts nothing: zero, not measured.
std::optional<std::size_t> allocated_bytes() {
#if defined(__GLIBC__)
    const struct mallinfo2 info = mallinfo2();
    const std::size_t bytes = info.uordblks + info.hblkhd;
    if (bytes == 0) return std::nullopt;
    return bytes;
#else
    return std::nullopt;
#endif
}

std::string megabytes(const std::optional<std::size_t>& bytes) {
    if (!bytes) return "not measured";
    return fixed(static_cast<double>(*bytes) / (1024.0 * 1024.0), 1) + " MiB";
}

// "what: 0.93x (bar: at most 1.50x) met".
std::string bar_line(const std::string& what, double ratio, double bar) {
    return what + ": " + fixed(ratio, 2) + "x (bar: at most " + fixed(bar, 2) + "x) " +
           (ratio <= bar ? "met" : "MISSED");
}

}  // namespace

SceneCost measure_scene_cost(const std::filesystem::path& path, int threads, int rounds,
                             double scale) {
    SceneCost best;
    best.load_seconds = best.build_seconds = best.render_seconds =
        std::numeric_limits<double>::infinity();
    for (int round = 0; round < rounds; ++round) {
        const std::optional<std::size_t> before = allocated_bytes();
        auto start = std::chrono::steady_clock::now();
        Scene scene = load_scene(path);
        best.load_seconds = std::min(best.load_seconds, seconds_since(start));
        scene.width = std::max(1, static_cast<int>(std::lround(scene.width * scale)));
        scene.height = std::max(1, static_cast<int>(std::lround(scene.height * scale)));

        start = std::chrono::steady_clock::now();
        const RenderScene render_scene = prepare_render_scene(scene);
        best.build_seconds = std::min(best.build_seconds, seconds_since(start));
        const std::optional<std::size_t> after = allocated_bytes();
        if (before && after) {
            const std::size_t grown = *after > *before ? *after - *before : 0;
            best.memory_bytes = std::max(best.memory_bytes.value_or(0), grown);
        }

        RenderOptions options;
        options.threads = threads;
        start = std::chrono::steady_clock::now();
        render_image(render_scene, options);
        best.render_seconds = std::min(best.render_seconds, seconds_since(start));
    }
    return best;
}

void run_scale_bars(const std::filesystem::path& scenes, int threads, bool quick) {
    const std::vector<std::string> names = {"spheres-1000", "mesh-127k", "one-bunny",
                                            "bunnies-1000"};
    std::error_code error;
    if (!std::filesystem::exists(scenes / "../meshes/bunny00.off", error)) {
        std::printf(
            "\nscale bars skipped: scenes/meshes/bunny00.off is missing (Debian's libcgal-demo; "
            "configure copies it there)\n");
        return;
    }
    for (const std::string& name : names) {
        const std::filesystem::path path = scenes / (name + ".test");
        if (!std::filesystem::exists(path, error)) {
            throw std::runtime_error("the scale scene " + path.string() + " is missing");
        }
    }
    const int rounds = quick ? 1 : 3;
    const double scale = quick ? 0.25 : 1.0;
    MarkdownTable table({"scene", "load (info)", "build", "render", "memory"});
    std::vector<SceneCost> costs;
    for (const std::string& name : names) {
        costs.push_back(measure_scene_cost(scenes / (name + ".test"), threads, rounds, scale));
        const SceneCost& cost = costs.back();
        table.add_row({name, fixed(cost.load_seconds, 4) + " s",
                       fixed(cost.build_seconds, 4) + " s", fixed(cost.render_seconds, 3) + " s",
                       megabytes(cost.memory_bytes)});
    }
    const SceneCost& spheres = costs[0];
    const SceneCost& mesh = costs[1];
    const SceneCost& one = costs[2];
    const SceneCost& thousand = costs[3];
    std::printf(
        "\n### scale: scenes/scale/, the full view at %s on %d threads, best of %d (build is "
        "prepare_render_scene: instances and every BVH)\n\n%s\n",
        quick ? "a quarter of each side" : "640 x 480", threads, rounds, table.text().c_str());

    const auto judge = [](const std::string& what, double ratio, double bar) {
        std::printf("- %s\n", bar_line(what, ratio, bar).c_str());
    };
    judge(
        "a thousand transformed spheres against the 127,408-triangle scene, load, build and "
        "render",
        (spheres.load_seconds + spheres.build_seconds + spheres.render_seconds) /
            (mesh.load_seconds + mesh.build_seconds + mesh.render_seconds),
        1.5);
    std::printf("- the same, render alone (the spheres fill more of the image): %sx\n",
                fixed(spheres.render_seconds / mesh.render_seconds, 2).c_str());
    judge("a thousand instanced bunnies against one, BVH build",
          thousand.build_seconds / one.build_seconds, 2.0);
    if (thousand.memory_bytes && one.memory_bytes && *one.memory_bytes > 0) {
        judge("a thousand instanced bunnies against one, memory",
              static_cast<double>(*thousand.memory_bytes) / static_cast<double>(*one.memory_bytes),
              2.0);
    } else {
        std::printf(
            "- a thousand instanced bunnies against one, memory: not measured (no glibc heap "
            "counts here)\n");
    }
    judge("raystep info (the load) on the mesh scene against its render (load, build, render)",
          mesh.load_seconds / (mesh.load_seconds + mesh.build_seconds + mesh.render_seconds), 0.2);
}

}  // namespace raystep
