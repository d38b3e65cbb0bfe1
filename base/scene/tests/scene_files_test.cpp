#include "base/scene/scene_files.h"

#include <filesystem>
#include <fstream>
#include <string>

#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"

using namespace raystep;
namespace fs = std::filesystem;

namespace {

const std::string kTriangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
const std::string kCameraLine = "camera 0 0 4 0 0 0 0 1 0 45\n";

void write(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

}  // namespace

TEST_CASE("scene_files: the scene file, then each mesh it draws or defines", "[base]") {
    const testing::ScratchFolder folder("scene-files");
    write(folder.path() / "a.off", kTriangle);
    write(folder.path() / "b.off", kTriangle);
    write(folder.path() / "two.test",
          "size 4 4\n" + kCameraLine + "mesh a.off\ndefine b b.off\ninstance b\n");
    const Scene scene = load_scene(folder.path() / "two.test");
    const std::vector<fs::path> files = scene_files(scene);
    REQUIRE(files.size() == 3);
    CHECK(files[0] == folder.path() / "two.test");
    CHECK(fs::equivalent(files[1], folder.path() / "a.off"));
    CHECK(fs::equivalent(files[2], folder.path() / "b.off"));
}

TEST_CASE("scene_digest: 64-bit FNV-1a of the files' bytes, then a boundary byte", "[base]") {
    const testing::ScratchFolder folder("scene-digest");
    write(folder.path() / "one.test", "size 1 1\n" + kCameraLine);
    // Computed apart from this code, in Python, over the file's bytes and the boundary byte 0xff.
    CHECK(scene_digest(load_scene(folder.path() / "one.test")) == "d51efb0c0f160222");
}

TEST_CASE("scene_digest: CRLF line ends change nothing, any other byte does, meshes included",
          "[base]") {
    const testing::ScratchFolder folder("scene-digest");
    const std::string text = "size 4 4\ncamera 0 0 4 0 0 0 0 1 0 45\nmesh a.off\n";
    write(folder.path() / "a.off", kTriangle);
    write(folder.path() / "lf.test", text);
    std::string crlf;
    for (const char c : text)
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    write(folder.path() / "crlf.test", crlf);
    const std::string digest = scene_digest(load_scene(folder.path() / "lf.test"));
    CHECK(digest.size() == 16);
    CHECK(scene_digest(load_scene(folder.path() / "crlf.test")) == digest);

    write(folder.path() / "lf.test", "size 4 4\ncamera 0 0 5 0 0 0 0 1 0 45\nmesh a.off\n");
    CHECK(scene_digest(load_scene(folder.path() / "lf.test")) != digest);
    write(folder.path() / "lf.test", text);
    write(folder.path() / "a.off", "OFF\n3 1 0\n0 0 0\n2 0 0\n0 1 0\n3 0 1 2\n");
    CHECK(scene_digest(load_scene(folder.path() / "lf.test")) != digest);
}

TEST_CASE("scene_digest: empty when a file of the scene cannot be read", "[base]") {
    const testing::ScratchFolder folder("scene-digest");
    write(folder.path() / "a.off", kTriangle);
    write(folder.path() / "mesh.test", "size 4 4\n" + kCameraLine + "mesh a.off\n");
    const Scene scene = load_scene(folder.path() / "mesh.test");
    fs::remove(folder.path() / "a.off");
    CHECK(scene_digest(scene).empty());
}
