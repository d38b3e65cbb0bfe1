#include "app/submit/submission_files.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "base/errors/input_error.h"

namespace raystep {

namespace fs = std::filesystem;

namespace {

// A stage folder's number: "3_intersect" -> 3, as the grader orders them.
int stage_number(const std::string& folder) {
    int number = 0;
    for (const char c : folder) {
        if (c < '0' || c > '9') break;
        number = number * 10 + (c - '0');
    }
    return number;
}

std::string trimmed(const std::string& line) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

fs::path find_repository_root(const fs::path& start) {
    const fs::path absolute = fs::absolute(start);
    for (fs::path folder = absolute;; folder = folder.parent_path()) {
        if (fs::is_directory(folder / "stages") &&
            fs::is_regular_file(folder / "CMakePresets.json"))
            return folder;
        if (folder == folder.root_path() || folder.parent_path() == folder) break;
    }
    throw std::runtime_error("no folder from " + absolute.string() +
                             " up holds stages/ and CMakePresets.json: run it inside your "
                             "raystep repository");
}

std::vector<SubmissionFile> submission_files(const fs::path& root) {
    std::vector<fs::path> stages;
    for (const auto& entry : fs::directory_iterator(root / "stages")) {
        if (entry.is_directory() && fs::is_regular_file(entry.path() / "manifest.txt"))
            stages.push_back(entry.path());
    }
    if (stages.empty())
        throw std::runtime_error((root / "stages").string() + " has no stage manifests");
    std::sort(stages.begin(), stages.end(), [](const fs::path& a, const fs::path& b) {
        return stage_number(a.filename().string()) < stage_number(b.filename().string());
    });

    std::vector<SubmissionFile> files;
    for (const fs::path& stage : stages) {
        const std::string folder = "stages/" + stage.filename().string();
        const std::string manifest = folder + "/manifest.txt";
        std::ifstream in(stage / "manifest.txt");
        int line_number = 0;
        for (std::string line; std::getline(in, line);) {
            ++line_number;
            const std::string file = trimmed(line);
            if (file.empty() || file.front() == '#') continue;
            SubmissionFile found;
            found.name = folder + "/" + file;
            found.path = stage / file;
            if (!fs::is_regular_file(found.path)) {
                throw InputError(
                    manifest, line_number,
                    "lists " + file + ", but " + found.name +
                        (fs::exists(found.path) ? " is not a file" : " does not exist") +
                        ": restore it (git checkout -- " + found.name + ")");
            }
            found.size = fs::file_size(found.path);
            found.stubs = still_stubbed(read_text(found.path));
            files.push_back(found);
        }
    }
    return files;
}

std::vector<std::string> still_stubbed(const std::string& source) {
    static const std::string kCall = "RAYSTEP_TODO(";
    std::vector<std::string> names;
    std::istringstream lines(source);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t call = line.find(kCall);
        if (call == std::string::npos) continue;
        const std::size_t comment = line.find("//");
        if (comment != std::string::npos && comment < call) continue;
        // The function's name is the call's first string: RAYSTEP_TODO(3, "intersect_sphere", ...)
        const std::size_t open = line.find('"', call);
        const std::size_t close = open == std::string::npos ? open : line.find('"', open + 1);
        names.push_back(close == std::string::npos ? "a function"
                                                   : line.substr(open + 1, close - open - 1));
    }
    return names;
}

}  // namespace raystep
