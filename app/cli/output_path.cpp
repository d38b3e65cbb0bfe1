#include "app/cli/output_path.h"

namespace raystep {

namespace fs = std::filesystem;

fs::path default_output(const fs::path& scene, const std::string& file_name) {
    const fs::path folder = kOutputFolder / scene.parent_path().filename();
    fs::create_directories(folder);
    return folder / fs::path(file_name).filename();
}

}  // namespace raystep
