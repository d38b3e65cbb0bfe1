// The reference's renders a grade keeps for the next (grader/grade/checks/kept_renders.h): read
// back bit for bit under the same key, and never under another or from a damaged entry.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"
#include "grader/grade/checks/kept_renders.h"

using raystep::Color;
using raystep::Image;
using raystep::grade::grader_identity;
using raystep::grade::keep_renders;
using raystep::grade::kept_renders;
using raystep::testing::ScratchFolder;

namespace fs = std::filesystem;

namespace {

std::vector<Image> two_renders() {
    std::vector<Image> renders = {Image(3, 2), Image(3, 2)};
    renders[0].set(2, 1, {0.1, 0.2, 1.0 / 3.0});
    renders[1].set(0, 0, {1e-30, 65504.0, 0.0});
    return renders;
}

bool same(const Image& a, const Image& b) {
    if (a.width() != b.width() || a.height() != b.height()) return false;
    for (int j = 0; j < a.height(); ++j) {
        for (int i = 0; i < a.width(); ++i) {
            const Color x = a.at(i, j);
            const Color y = b.at(i, j);
            if (x.r != y.r || x.g != y.g || x.b != y.b) return false;
        }
    }
    return true;
}

// The entry file keep_renders wrote: the only file in the folder.
fs::path only_entry(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        files.push_back(entry.path());
    REQUIRE(files.size() == 1);
    return files.front();
}

}  // namespace

TEST_CASE("renders kept under a key are read back bit for bit under that key alone", "[grader]") {
    const ScratchFolder folder("kept-renders");
    const std::vector<Image> renders = two_renders();
    keep_renders(folder.path(), "scene 1\nview full\n", renders);
    const std::optional<std::vector<Image>> kept =
        kept_renders(folder.path(), "scene 1\nview full\n");
    REQUIRE(kept);
    REQUIRE(kept->size() == 2);
    CHECK(same((*kept)[0], renders[0]));
    CHECK(same((*kept)[1], renders[1]));
    CHECK_FALSE(kept_renders(folder.path(), "scene 2\nview full\n"));
}

TEST_CASE("an entry is read only when the key it holds is the one asked for, and it is whole",
          "[grader]") {
    const ScratchFolder folder("kept-renders");
    keep_renders(folder.path(), "scene 1\n", two_renders());
    const fs::path entry = only_entry(folder.path());

    SECTION("an entry found under another key's name, as a hash that collides would find it") {
        keep_renders(folder.path() / "other", "scene 2\n", two_renders());
        const fs::path other = only_entry(folder.path() / "other");
        fs::copy_file(entry, other, fs::copy_options::overwrite_existing);
        CHECK_FALSE(kept_renders(folder.path() / "other", "scene 2\n"));
    }
    SECTION("an entry cut short") {
        fs::resize_file(entry, fs::file_size(entry) - 1);
        CHECK_FALSE(kept_renders(folder.path(), "scene 1\n"));
    }
    SECTION("an entry with bytes after its renders") {
        std::ofstream(entry, std::ios::binary | std::ios::app) << "x";
        CHECK_FALSE(kept_renders(folder.path(), "scene 1\n"));
    }
}

TEST_CASE("the grader's identity names its program and stays the same within a run", "[grader]") {
    const std::string identity = grader_identity();
    CHECK(identity.find("raystep_grader_tests") != std::string::npos);
    CHECK(grader_identity() == identity);
}
