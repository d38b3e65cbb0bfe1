#include "grader/grade/submission.h"

#include <algorithm>
#include <stdexcept>
#include <system_error>

#include "grader/sandbox/sandbox.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

constexpr std::uintmax_t kLargestFile = 1u << 20;
constexpr std::size_t kMostEntries = 20000;  // a submission is a few dozen files

// Every regular file under `root`, by path relative to it; links and special files are skipped,
// and so is anything past kMostEntries.
std::vector<fs::path> regular_files(const fs::path& root) {
    std::vector<fs::path> files;
    std::error_code error;
    fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, error);
    std::size_t seen = 0;
    for (; !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
        if (++seen > kMostEntries) break;
        const fs::file_status status = it->symlink_status(error);
        if (error) break;
        if (fs::is_regular_file(status)) files.push_back(fs::relative(it->path(), root));
    }
    return files;
}

fs::path unpack_zip(const fs::path& zip, const fs::path& into, const ProbeToolchain& toolchain) {
    fs::create_directories(into);
    SandboxPolicy policy;
    policy.read_only = {fs::absolute(zip).parent_path()};
    policy.writable = into;
    policy.working_directory = into;
    policy.limits.cpu_seconds = 20;
    policy.limits.wall = std::chrono::seconds(40);
    policy.limits.file_size_bytes = 16u << 20;
    const SandboxRun run =
        run_sandboxed({toolchain.cmake.string(), "-E", "tar", "xf", fs::absolute(zip).string()}, "",
                      policy);
    if (run.exit_code != 0) {
        throw std::runtime_error(zip.string() + ": could not be unpacked as a zip file: " +
                                 run.errors.substr(0, 400));
    }
    return into;
}

// The candidate for `file` of stage `folder`: stages/<folder>/<file> if present, else the
// shallowest file of that name.
const fs::path* choose(const std::vector<fs::path>& files, const std::string& folder,
                       const std::string& file, std::string& note) {
    const fs::path* best = nullptr;
    std::size_t named = 0;
    for (const fs::path& candidate : files) {
        if (candidate.filename() != file) continue;
        ++named;
        const bool in_stage = candidate.parent_path().filename() == folder;
        const bool best_in_stage = best && best->parent_path().filename() == folder;
        const auto depth = [](const fs::path& p) { return std::distance(p.begin(), p.end()); };
        if (!best || (in_stage && !best_in_stage) ||
            (in_stage == best_in_stage && depth(candidate) < depth(*best))) {
            best = &candidate;
        }
    }
    if (named > 1) note = file + ": " + std::to_string(named) + " files of that name; took " + best->string();
    return best;
}

}  // namespace

Submission take_submission(const fs::path& path, const std::vector<StageManifest>& manifests,
                           const fs::path& work, const ProbeToolchain& toolchain) {
    std::error_code error;
    fs::path root;
    if (fs::is_directory(path, error)) {
        root = path;
    } else if (fs::is_regular_file(path, error) && path.extension() == ".zip") {
        root = unpack_zip(path, work / "unpacked", toolchain);
    } else {
        throw std::runtime_error(path.string() + ": neither a folder nor a .zip file");
    }
    const std::vector<fs::path> files = regular_files(root);

    Submission submission;
    submission.name = fs::absolute(path).lexically_normal().filename().replace_extension().string();
    if (submission.name.empty()) submission.name = fs::absolute(path).parent_path().filename().string();
    submission.tree = work / "submission";
    for (const StageManifest& manifest : manifests) {
        SubmittedStage stage;
        stage.manifest = manifest;
        const fs::path folder = submission.tree / "stages" / manifest.folder;
        fs::create_directories(folder);
        for (const std::string& file : manifest.files) {
            std::string note;
            const fs::path* found = choose(files, manifest.folder, file, note);
            if (!note.empty()) stage.notes.push_back(note);
            if (!found || fs::file_size(root / *found, error) > kLargestFile || error) {
                stage.missing.push_back(file);
                continue;
            }
            fs::copy_file(root / *found, folder / file, fs::copy_options::overwrite_existing);
            stage.files.push_back(folder / file);
        }
        submission.stages.push_back(stage);
    }
    return submission;
}

}  // namespace raystep::grade
