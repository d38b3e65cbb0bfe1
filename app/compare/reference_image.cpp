#include "app/compare/reference_image.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "base/errors/input_error.h"
#include "renderer/view.h"

namespace raystep {

namespace fs = std::filesystem;

namespace {

bool ends_with(const std::string& text, const std::string& tail) {
    return text.size() >= tail.size() &&
           text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// The reference folders a render's reference may be in, nearest first: the one beside the image
// (a render written next to its scene), then every stage's under ./scenes (a render written
// anywhere else, from the repository's root); each once.
std::vector<fs::path> reference_folders(const fs::path& image) {
    std::vector<fs::path> folders = {image.parent_path() / "reference"};
    std::error_code error;
    std::vector<fs::path> stages;
    for (const auto& entry : fs::directory_iterator("scenes", error)) {
        if (fs::is_directory(entry.path() / "reference")) stages.push_back(entry.path());
    }
    std::sort(stages.begin(), stages.end());
    const fs::path beside = fs::weakly_canonical(folders.front(), error);
    for (const fs::path& stage : stages) {
        if (fs::weakly_canonical(stage / "reference", error) != beside)
            folders.push_back(stage / "reference");
    }
    return folders;
}

// The references of one scene, `<scene>.<view>.png`, in the folders: what a student can choose
// from when the view is wrong or missing.
std::vector<std::string> references_of(const std::string& scene,
                                       const std::vector<fs::path>& folders) {
    std::vector<std::string> found;
    for (const fs::path& folder : folders) {
        std::error_code error;
        for (const auto& entry : fs::directory_iterator(folder, error)) {
            const std::string name = entry.path().filename().string();
            if (name.rfind(scene + ".", 0) == 0 && entry.path().extension() == ".png")
                found.push_back(entry.path().string());
        }
    }
    std::sort(found.begin(), found.end());
    return found;
}

}  // namespace

std::vector<std::string> reference_views(const fs::path& scene) {
    std::ifstream in(scene);
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (line.rfind("# views:", 0) != 0) continue;
        std::istringstream words(line.substr(8));
        std::vector<std::string> views;
        for (std::string view; words >> view;) {
            if (!parse_view(view)) {
                std::string known;
                for (const std::string& name : view_names())
                    known += (known.empty() ? "" : ", ") + name;
                throw InputError(
                    scene.string(), number,
                    "'# views:' names '" + view + "', which is no view (" + known + ")");
            }
            views.push_back(view);
        }
        return views;
    }
    return {"full"};
}

fs::path reference_image_path(const fs::path& scene, std::string_view view) {
    return scene.parent_path() / "reference" /
           (scene.stem().string() + "." + std::string(view) + ".png");
}

fs::path reference_trace_path(const fs::path& scene) {
    return scene.parent_path() / "reference" / (scene.stem().string() + ".trace.exr");
}

fs::path find_reference_image(const fs::path& image, const std::string& view) {
    std::string name = image.stem().string();
    if (!view.empty() && !ends_with(name, "." + view)) name += "." + view;
    const std::vector<fs::path> folders = reference_folders(image);
    for (const fs::path& folder : folders) {
        if (fs::is_regular_file(folder / (name + ".png"))) return folder / (name + ".png");
    }

    // Say what there is: the scene's other views, or where references come from.
    const std::string scene = name.substr(0, name.find('.'));
    const std::vector<std::string> others = references_of(scene, folders);
    std::string problem = "no reference image " + name + ".png in " +
                          (image.parent_path() / "reference").string() + " or scenes/*/reference";
    if (!others.empty()) {
        problem += "; the references of " + scene + " are:";
        for (const std::string& other : others)
            problem += " " + other;
        problem += " (pick one with --view VIEW, or give it as REFERENCE)";
    } else {
        problem +=
            "; give the reference image as REFERENCE (a student release has each scene's "
            "views in scenes/<stage>/reference/)";
    }
    throw InputError(image.string(), 0, problem);
}

}  // namespace raystep
