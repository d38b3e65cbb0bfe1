// What `raystep submit` packs (app/submit/submission_files.h): the repository found from inside it,
// the manifests' files in stage order, a missing one named by manifest and line, stubs found.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/submit/submission_files.h"
#include "base/errors/input_error.h"
#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"

using namespace raystep;

namespace fs = std::filesystem;

namespace {

void write_file(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

// A repository as the student has one: CMakePresets.json, and two stages whose manifests list
// their files, the later stage's folder named first.
void write_repository(const fs::path& root) {
    write_file(root / "CMakePresets.json", "{}\n");
    write_file(root / "stages/10_extra/manifest.txt", "extra.cpp\n");
    write_file(root / "stages/10_extra/extra.cpp", "// done\n");
    write_file(root / "stages/2_rays/manifest.txt", "# Stage 2\n\n  camera.cpp \r\nray.cpp\n");
    write_file(root / "stages/2_rays/camera.cpp", "int camera;\n");
    write_file(root / "stages/2_rays/ray.cpp", "    RAYSTEP_TODO(2, \"Ray::at\", \"Rays\");\n");
    write_file(root / "stages/2_rays/notes.txt", "not listed\n");
}

std::vector<std::string> names(const std::vector<SubmissionFile>& files) {
    std::vector<std::string> result;
    for (const SubmissionFile& file : files)
        result.push_back(file.name);
    return result;
}

}  // namespace

TEST_CASE("find_repository_root: the nearest folder up with stages/ and CMakePresets.json",
          "[submit]") {
    const testing::ScratchFolder scratch("submit-root");
    write_repository(scratch.path());
    fs::create_directories(scratch.path() / "stages/2_rays/tests");
    CHECK(find_repository_root(scratch.path() / "stages/2_rays/tests") == scratch.path());
    CHECK(find_repository_root(scratch.path()) == scratch.path());
    CHECK_THROWS_WITH(find_repository_root(scratch.path().parent_path()),
                      Catch::Contains("run it inside your raystep repository"));
}

TEST_CASE("submission_files: the manifests' files in stage order, trimmed, nothing else",
          "[submit]") {
    const testing::ScratchFolder scratch("submit-files");
    write_repository(scratch.path());
    const std::vector<SubmissionFile> files = submission_files(scratch.path());
    CHECK(names(files) == std::vector<std::string>{"stages/2_rays/camera.cpp",
                                                   "stages/2_rays/ray.cpp",
                                                   "stages/10_extra/extra.cpp"});
    CHECK(files[0].size == 12);
    CHECK(files[0].stubs.empty());
    CHECK(files[1].stubs == std::vector<std::string>{"Ray::at"});
}

TEST_CASE("submission_files: a listed file that is missing names the manifest and its line",
          "[submit]") {
    const testing::ScratchFolder scratch("submit-missing");
    write_repository(scratch.path());
    fs::remove(scratch.path() / "stages/2_rays/ray.cpp");
    CHECK_THROWS_WITH(submission_files(scratch.path()),
                      "stages/2_rays/manifest.txt:4: lists ray.cpp, but stages/2_rays/ray.cpp "
                      "does not exist: restore it (git checkout -- stages/2_rays/ray.cpp)");
}

TEST_CASE("still_stubbed: the names of the RAYSTEP_TODO calls left, not those in comments",
          "[submit]") {
    CHECK(still_stubbed("double dot() {\n    RAYSTEP_TODO(1, \"dot\", \"Dot product\");\n}\n"
                        "// Replace each RAYSTEP_TODO with your code\n"
                        "    // RAYSTEP_TODO(1, \"cross\", \"Cross product\");\n"
                        "    RAYSTEP_TODO(1, \"length\", \"Length\");\n") ==
          std::vector<std::string>{"dot", "length"});
    CHECK(
        still_stubbed("double dot(const Vec3& a, const Vec3& b) { return a.x * b.x; }\n").empty());
}
