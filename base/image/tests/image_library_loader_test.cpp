#include "base/image/image_library_loader.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"

using namespace raystep;

namespace {

// The message of the error load_image_library throws for these candidates; "" when it loads.
std::string load_failure(const std::vector<std::filesystem::path>& candidates) {
    try {
        load_image_library(candidates);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST_CASE("load_image_library: names each path tried with the system loader's reason", "[base]") {
    const testing::ScratchFolder scratch("image-library-loader-test");
    const std::filesystem::path missing = scratch.path() / "no-such-module.so";
    const std::filesystem::path not_a_module = scratch.path() / "not-a-module.so";
    std::ofstream(not_a_module) << "an image library, honestly\n";

    const std::string message = load_failure({missing, not_a_module});
    CAPTURE(message);
    CHECK(message.find("cannot load the image library") != std::string::npos);
    CHECK(message.find(missing.string() + ": ") != std::string::npos);
    CHECK(message.find(not_a_module.string() + ": ") != std::string::npos);
#ifdef __linux__
    CHECK(message.find("No such file") != std::string::npos);
#endif
}

TEST_CASE("load_image_library: falls back to the next path, the module this build made", "[base]") {
    const testing::ScratchFolder scratch("image-library-loader-test");
    const RaystepImageLibraryTable& table =
        load_image_library({scratch.path() / "no-such-module.so", RAYSTEP_IMAGE_LIBRARY_PATH});
    CHECK(table.version == RAYSTEP_IMAGE_LIBRARY_VERSION);
    CHECK(&table == &image_library());
}
