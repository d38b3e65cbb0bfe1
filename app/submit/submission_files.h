#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raystep {

/// One file a stage's manifest.txt lists, as `raystep submit` packs it.
struct SubmissionFile {
    std::string name;            ///< in the zip and the repository: "stages/3_intersect/sphere.cpp"
    std::filesystem::path path;  ///< on disk
    std::uintmax_t size = 0;     ///< bytes
    std::vector<std::string> stubs;  ///< functions still ending in RAYSTEP_TODO (still_stubbed)
};

/// The repository holding `start`: the nearest folder from `start` up that holds a stages/
/// folder and CMakePresets.json. Throws std::runtime_error naming `start` when there is none.
std::filesystem::path find_repository_root(const std::filesystem::path& start);

/// Every file the manifests stages/*/manifest.txt of the repository at `root` list, in stage
/// order and then the manifest's order. A manifest is read as the grader reads it
/// (grader/grade/stage_manifests.cpp): one file name a line, blanks and `#` lines skipped,
/// spaces around a name trimmed. Throws InputError naming the manifest and line of a listed file
/// that is missing or not a regular file, and std::runtime_error when no stage has a manifest.
std::vector<SubmissionFile> submission_files(const std::filesystem::path& root);

/// The functions of a stage file whose stubs are still there: the names of its
/// `RAYSTEP_TODO(stage, "name", ...)` calls, in order, leaving out those after `//` on a line.
/// A function is written once its RAYSTEP_TODO is gone, so a file whose functions the student
/// wrote never appears here; a file that never held a stub (a dispatcher) never does either.
std::vector<std::string> still_stubbed(const std::string& source);

}  // namespace raystep
