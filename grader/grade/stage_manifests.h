#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace raystep::grade {

/// A stage as the grader takes it from a submission: its folder and the files its manifest.txt
/// lists, which are all the grader takes from a submission, and nothing else
/// (ARCHITECTURE.md, "Student code or the reference").
struct StageManifest {
    int number = 0;
    std::string folder;              ///< "3_intersect"
    std::vector<std::string> files;  ///< "sphere.cpp", ...
};

/// Every stages/N_topic/manifest.txt of the repository at `source`, in stage order.
std::vector<StageManifest> read_stage_manifests(const std::filesystem::path& source);

}  // namespace raystep::grade
