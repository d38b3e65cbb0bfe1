#include "studies/structures/bench_scenes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "studies/common/number_text.h"
#include "studies/structures/bench_geometry.h"
#include "studies/structures/bench_rays.h"

namespace raystep {

namespace {

// The seeds of the seeded scenes and rays: fixed, so that every run measures the same work.
constexpr std::uint64_t kSphereSeed = 2026;
constexpr std::uint64_t kIncoherentSeed = 167;

constexpr int kPrimarySide = 512;
constexpr std::size_t kIncoherentRays = std::size_t{1} << 18;
constexpr std::size_t kSphereCount = 10000;

// 16 bunnies: a 4 x 4 array spaced by 1.5 times the mesh's extent, so neighbours do not touch
constexpr int kTiles = 4;
constexpr double kTileSpacing = 1.5;

// The primary and incoherent ray sets of a scene, scaled down by `fraction` in count (the
// primary image keeps its square shape).
std::vector<RaySet> scene_ray_sets(const std::string& name, const PrimitiveList& primitives,
                                   double fraction) {
    const Aabb box = bench_bounds(primitives);
    const int side = std::max(1, static_cast<int>(std::lround(kPrimarySide * std::sqrt(fraction))));
    const auto incoherent = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::llround(static_cast<double>(kIncoherentRays) * fraction)));
    return {
        {name + "-primary", std::to_string(side) + " x " + std::to_string(side) + " primary rays",
         primary_rays(box, side, side)},
        {name + "-incoherent",
         grouped(incoherent) + " incoherent rays (from a sphere around the scene into its box)",
         incoherent_rays(box, incoherent, kIncoherentSeed)},
    };
}

}  // namespace

std::vector<std::string> bench_scene_names() {
    return {"bunny", "bunnies16", "spheres"};
}

std::vector<std::string> bench_workload_names() {
    std::vector<std::string> names;
    for (const std::string& scene : bench_scene_names()) {
        names.push_back(scene);
        names.push_back(scene + "-primary");
        names.push_back(scene + "-incoherent");
    }
    return names;
}

std::optional<std::string> bench_scene_unavailable(const std::string& name,
                                                   const std::filesystem::path& mesh_folder) {
    if (name != "bunny" && name != "bunnies16") return std::nullopt;
    const std::filesystem::path mesh = mesh_folder / kBunnyFile;
    std::error_code error;
    if (std::filesystem::is_regular_file(mesh, error)) return std::nullopt;
    return mesh.string() +
           " is missing: Debian's libcgal-demo provides it (in "
           "/usr/share/doc/libcgal-dev/data.tar.gz, which CMake extracts when it configures; "
           "scripts/install-deps.sh installs it, then configure again)";
}

BenchScene make_bench_scene(const std::string& name, const std::filesystem::path& mesh_folder,
                            double ray_fraction) {
    BenchScene scene;
    scene.name = name;
    if (name == "bunny" || name == "bunnies16") {
        const std::vector<Triangle> bunny = mesh_triangles(load_mesh(mesh_folder / kBunnyFile));
        if (name == "bunny") {
            scene.primitives.triangles = bunny;
            scene.description =
                std::string(kBunnyFile) + ", " + grouped(bunny.size()) + " triangles";
        } else {
            scene.primitives.triangles = tiled_copies(bunny, kTiles, kTiles, kTileSpacing);
            scene.description = "16 copies of " + std::string(kBunnyFile) + " in a 4 x 4 array, " +
                                grouped(scene.primitives.triangles.size()) + " triangles";
        }
    } else if (name == "spheres") {
        scene.primitives.spheres = random_spheres(kSphereCount, kSphereSeed);
        scene.description = grouped(kSphereCount) + " random spheres in the unit cube";
    } else {
        throw std::invalid_argument("no bench scene '" + name + "'");
    }
    scene.ray_sets = scene_ray_sets(name, scene.primitives, ray_fraction);
    return scene;
}

}  // namespace raystep
