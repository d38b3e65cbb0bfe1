#include "app/cli/sampling_options.h"

#include <stdexcept>

#include "base/testing/catch.h"

using namespace raystep;

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
