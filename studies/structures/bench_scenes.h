#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "studies/structures/measurement.h"

namespace raystep {

/// A scene the bench measures, with its ray sets: a workload is a scene and one of its ray sets.
struct BenchScene {
    std::string name;         ///< "bunny", "bunnies16", "spheres"
    std::string description;  ///< what it is made of, for the tables' titles
    PrimitiveList primitives;
    std::vector<RaySet> ray_sets;  ///< "<name>-primary", then "<name>-incoherent"
};

/// The scenes in the order the bench runs them: "bunny" (bunny00.off), "bunnies16" (16 copies
/// of it) and "spheres" (10,000 random spheres).
std::vector<std::string> bench_scene_names();

/// What --workload accepts: each scene's name (both its ray sets) and each workload's name,
/// "<scene>-primary" or "<scene>-incoherent".
std::vector<std::string> bench_workload_names();

/// The mesh file the bunny scenes are made of, which CMake extracts from Debian's libcgal-demo
/// into the build folder.
inline constexpr const char* kBunnyFile = "bunny00.off";

/// Why the scene cannot be made (its mesh is not in `mesh_folder`, and where to get it), or
/// nullopt when it can.
std::optional<std::string> bench_scene_unavailable(const std::string& name,
                                                   const std::filesystem::path& mesh_folder);

/// The scene and its two ray sets: 512 x 512 primary rays and 2^18 incoherent rays, both
/// numbers times `ray_fraction` (--quick makes it 1/8). Throws InputError when a mesh file is
/// missing or malformed, std::invalid_argument for an unknown name.
BenchScene make_bench_scene(const std::string& name, const std::filesystem::path& mesh_folder,
                            double ray_fraction);

}  // namespace raystep
