#include "app/cli/output_path.h"

namespace raystep {

namespace fs = std::filesystem;

fs::path default_output(const std::string& folder, const std::string& file_name) {
    const fs::path where = kOutputFolder / folder;
    fs::create_directories(where);
    return where / fs::path(file_name).filename();
}

std::string scene_output_folder(const fs::path& scene) {
    return scene.parent_path().filename().string();
}

}  // namespace raystep
