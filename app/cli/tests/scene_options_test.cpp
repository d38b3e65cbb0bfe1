#include "app/cli/scene_options.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "base/testing/catch.h"

using namespace raystep;

namespace {

// `--lookfrom` parsed from `words` (the program's name first, as on a command line).
std::vector<double> parsed_eye(std::vector<std::string> words) {
    CLI::App app;
    std::vector<double> lookfrom;
    add_eye_option(app, lookfrom);
    std::vector<const char*> argv;
    for (const std::string& word : words)
        argv.push_back(word.c_str());
    app.parse(static_cast<int>(argv.size()), argv.data());
    return lookfrom;
}

}  // namespace

TEST_CASE("add_eye_option: three numbers, read back as the same doubles", "[app]") {
    CHECK(parsed_eye({"raystep"}).empty());
    CHECK(parsed_eye({"raystep", "--lookfrom", "0.1", "-2", "3.0000000000000004"}) ==
          std::vector<double>{0.1, -2.0, 3.0000000000000004});
}

TEST_CASE("add_eye_option: two numbers, four, or a word are command-line errors", "[app]") {
    CHECK_THROWS_AS(parsed_eye({"raystep", "--lookfrom", "1", "2"}), CLI::ParseError);
    CHECK_THROWS_AS(parsed_eye({"raystep", "--lookfrom", "1", "2", "3", "4"}), CLI::ParseError);
    CHECK_THROWS_AS(parsed_eye({"raystep", "--lookfrom", "1", "two", "3"}), CLI::ParseError);
    CHECK_THROWS_AS(parsed_eye({"raystep", "--lookfrom", "1", "inf", "3"}), CLI::ParseError);
}

TEST_CASE("apply_eye: moves the eye and keeps the rest of the camera", "[app]") {
    Scene scene;
    scene.camera = {Vec3(0, 0, 4), Vec3(0, 1, 0), Vec3(0, 1, 0), 45.0, {}, 3};
    apply_eye({}, scene);
    CHECK(scene.camera.lookfrom == Vec3(0, 0, 4));
    apply_eye({1.5, 2.0, 3.5}, scene);
    CHECK(scene.camera.lookfrom == Vec3(1.5, 2.0, 3.5));
    CHECK(scene.camera.lookat == Vec3(0, 1, 0));
    CHECK(scene.camera.up == Vec3(0, 1, 0));
    CHECK(scene.camera.fovy_degrees == 45.0);
}

TEST_CASE("apply_eye: an eye at the look-at point is refused, not a camera that sees nothing",
          "[app]") {
    Scene scene;
    scene.camera = {Vec3(0, 0, 4), Vec3(0, 1, 0), Vec3(0, 1, 0), 45.0, {}, 3};
    CHECK_THROWS_AS(apply_eye({0.0, 1.0, 0.0}, scene), std::invalid_argument);
    CHECK(scene.camera.lookfrom == Vec3(0, 0, 4));
}

TEST_CASE("apply_sampling: each option given replaces the scene's setting, the rest stay",
          "[app]") {
    Scene scene;
    scene.samples_per_pixel = 4;
    scene.seed = 3;
    SamplingArguments arguments;
    arguments.samples_per_pixel = 16;
    apply_sampling(arguments, scene);
    CHECK(scene.samples_per_pixel == 16);
    CHECK(scene.seed == 3);
    CHECK(scene.pixel_sampling == SamplePattern::jittered);
    arguments.pixel_sampling = "random";
    arguments.seed = 11;
    apply_sampling(arguments, scene);
    CHECK(scene.pixel_sampling == SamplePattern::random);
    CHECK(scene.seed == 11);
}

TEST_CASE("apply_sampling: a count that is not a square cannot be jittered or regular", "[app]") {
    Scene scene;
    SamplingArguments arguments;
    arguments.samples_per_pixel = 8;
    CHECK_THROWS_AS(apply_sampling(arguments, scene), std::invalid_argument);
    arguments.pixel_sampling = "regular";
    CHECK_THROWS_AS(apply_sampling(arguments, scene), std::invalid_argument);
    arguments.pixel_sampling = "random";
    CHECK_NOTHROW(apply_sampling(arguments, scene));
    CHECK(scene.samples_per_pixel == 8);
}
