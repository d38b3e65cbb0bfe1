#include "app/compare/reference_image.h"

#include <fstream>

#include "base/errors/input_error.h"
#include "base/image/image_io.h"
#include "base/testing/catch.h"
#include "base/testing/filled_image.h"
#include "base/testing/scratch_folder.h"

using namespace raystep;
namespace fs = std::filesystem;

TEST_CASE("reference_image_path: the release's reference folder beside the scene", "[app]") {
    CHECK(reference_image_path("scenes/stage2/orthographic.test", "rays") ==
          fs::path("scenes/stage2/reference/orthographic.rays.png"));
}

TEST_CASE("reference_views: the scene's views line, or full without one", "[app]") {
    const fs::path stage2 = fs::path(RAYSTEP_SOURCE_DIR) / "scenes" / "stage2";
    CHECK(reference_views(stage2 / "perspective-wide.test") ==
          std::vector<std::string>{"rays", "depth"});
    CHECK(reference_views(fs::path(RAYSTEP_TEST_DATA) / "good" / "quad.test") ==
          std::vector<std::string>{"full"});
}

TEST_CASE("reference_views: a word that is no view is an error naming the scene's line", "[app]") {
    const raystep::testing::ScratchFolder folder("reference-views");
    const fs::path scene = folder.path() / "typo.test";
    std::ofstream(scene) << "size 4 4\n# views: rays shiny\n";
    CHECK_THROWS_WITH(reference_views(scene),
                      Catch::Matchers::Contains("typo.test:2") &&
                          Catch::Matchers::Contains("'shiny', which is no view"));
}

TEST_CASE("reference_views: every scene the release renders names views that exist", "[app]") {
    for (const auto& entry :
         fs::recursive_directory_iterator(fs::path(RAYSTEP_SOURCE_DIR) / "scenes")) {
        if (entry.path().extension() != ".test") continue;
        INFO(entry.path());
        CHECK_FALSE(reference_views(entry.path()).empty());
    }
}

TEST_CASE("find_reference_image: by the image's name, or its scene's name and a view", "[app]") {
    const raystep::testing::ScratchFolder folder("reference-image");
    const fs::path reference = folder.path() / "reference" / "quad.normal.png";
    write_image(raystep::testing::filled_image(2, 2, Color(0.5)), reference);

    CHECK(find_reference_image(folder.path() / "quad.normal.png", "") == reference);
    CHECK(find_reference_image(folder.path() / "quad.normal.png", "normal") == reference);
    CHECK(find_reference_image(folder.path() / "quad.png", "normal") == reference);
}

TEST_CASE("find_reference_image: none names the image and lists the scene's references", "[app]") {
    const raystep::testing::ScratchFolder folder("reference-image");
    const fs::path reference = folder.path() / "reference" / "quad.normal.png";
    write_image(raystep::testing::filled_image(2, 2, Color(0.5)), reference);

    CHECK_THROWS_AS(find_reference_image(folder.path() / "quad.depth.png", ""), InputError);
    CHECK_THROWS_WITH(find_reference_image(folder.path() / "quad.depth.png", ""),
                      Catch::StartsWith((folder.path() / "quad.depth.png").string()) &&
                          Catch::Contains("no reference image quad.depth.png") &&
                          Catch::Contains("the references of quad are: " + reference.string()));
    CHECK_THROWS_WITH(find_reference_image(folder.path() / "cube.png", ""),
                      Catch::Contains("give the reference image as REFERENCE"));
}
