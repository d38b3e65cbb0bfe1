#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace raystep::grade {

/// How this build compiles and links a probe (grader/CMakeLists.txt writes it at configure time
/// as probe-toolchain.json beside the grader): the compiler and flags the reference stages were
/// built with, so a submission's files are compiled the same way, and everything a probe links.
struct ProbeToolchain {
    std::filesystem::path compiler;
    std::vector<std::string> compile_flags;
    /// Taken first by every compile of a submission's file (`-include`), precompiled beside it
    /// with compile_flags (probe_precompiled.h); empty: none.
    std::filesystem::path precompiled_header;
    std::vector<std::filesystem::path> probe_objects;  ///< the calls, the renderer, app/check
    std::vector<std::filesystem::path> libraries;      ///< below the stages: protocol, scene, core
    std::vector<std::string> link_flags;
    /// The compiler's LTO plugin, which nm is told to load alone rather than every plugin
    /// installed beside binutils (LLVM's among them); empty: nm chooses.
    std::filesystem::path nm_plugin;
    /// The image library module (base/image/image_library_loader.h), which a probe loads to read
    /// a scene's texture: copied where the sandbox's user can read it (ProbeSet::image_library).
    std::filesystem::path image_module;
    std::map<int, std::filesystem::path> stage_libraries;  ///< each stage's reference library
    std::filesystem::path source;  ///< the repository: its base/ and stages/ headers, scenes/
};

/// Reads probe-toolchain.json. Throws std::runtime_error naming the file when it is missing or
/// malformed (the grader's build is broken: rerun cmake).
ProbeToolchain load_probe_toolchain(const std::filesystem::path& file);

/// The toolchain of this build of raystep-grade.
ProbeToolchain this_build_toolchain();

}  // namespace raystep::grade
