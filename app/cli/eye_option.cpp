#include "app/cli/eye_option.h"

#include <stdexcept>

#include "app/cli/finite_number_check.h"

namespace raystep {

void add_eye_option(CLI::App& command, std::vector<double>& lookfrom) {
    command
        .add_option("--lookfrom", lookfrom,
                    "Render from this eye instead of the scene's: three numbers, the rest of the "
                    "camera kept")
        ->expected(3)
        ->check(finite_number_check("X Y Z", "the eye's coordinates are numbers"));
}

void apply_eye(const std::vector<double>& lookfrom, Scene& scene) {
    if (lookfrom.empty()) return;
    const Vec3 eye(lookfrom[0], lookfrom[1], lookfrom[2]);
    if (eye == scene.camera.lookat) {
        throw std::invalid_argument(
            "--lookfrom is the scene's look-at point: from there the camera looks nowhere");
    }
    scene.camera.lookfrom = eye;
}

}  // namespace raystep
