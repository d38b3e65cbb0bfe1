#include "grader/grade/stage_manifests.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace raystep::grade {

std::vector<StageManifest> read_stage_manifests(const std::filesystem::path& source) {
    std::vector<StageManifest> stages;
    for (const auto& entry : std::filesystem::directory_iterator(source / "stages")) {
        const std::filesystem::path manifest = entry.path() / "manifest.txt";
        if (!entry.is_directory() || !std::filesystem::exists(manifest)) continue;
        StageManifest stage;
        stage.folder = entry.path().filename().string();
        stage.number = std::stoi(stage.folder);
        std::ifstream in(manifest);
        for (std::string line; std::getline(in, line);) {
            const auto first = line.find_first_not_of(" \t\r");
            if (first == std::string::npos || line[first] == '#') continue;
            stage.files.push_back(line.substr(first, line.find_last_not_of(" \t\r") - first + 1));
        }
        stages.push_back(stage);
    }
    if (stages.empty())
        throw std::runtime_error(source.string() + "/stages has no stage manifests");
    std::sort(stages.begin(), stages.end(),
              [](const StageManifest& a, const StageManifest& b) { return a.number < b.number; });
    return stages;
}

}  // namespace raystep::grade
