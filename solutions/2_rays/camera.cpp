// Stage 2 reference solution: cameras.

#include "stages/2_rays/camera.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/trigonometric.hpp>

#include "base/math/to_text.h"

namespace raystep {

namespace {

void check_image_size(int width, int height) {
    if (width < 1 || height < 1) {
        throw std::domain_error("camera: image size " + std::to_string(width) + " x " +
                                std::to_string(height) + " has no pixels");
    }
}

// The pixel centre (i + 0.5, j + 0.5) as fractions of the image, from 0 at the left and bottom
// edges to 1 at the right and top ones. Rows count down from the top.
double column_fraction(int i, int width) {
    return (i + 0.5) / width;
}
double row_fraction(int j, int height) {
    return 1.0 - (j + 0.5) / height;
}

}  // namespace

PerspectiveCamera make_perspective_camera(const Vec3& lookfrom, const Vec3& lookat, const Vec3& up,
                                          double fovy_degrees, int width, int height) {
    if (!(fovy_degrees > 0.0 && fovy_degrees < 180.0)) {
        throw std::domain_error("camera: fovy " + to_text(fovy_degrees) +
                                " is not strictly between 0 and 180 degrees");
    }
    check_image_size(width, height);
    PerspectiveCamera camera;
    camera.eye = lookfrom;
    camera.frame = orthonormal_frame(lookfrom - lookat, up);
    camera.half_height = std::tan(glm::radians(fovy_degrees) / 2.0);
    camera.half_width = camera.half_height * width / height;
    camera.width = width;
    camera.height = height;
    return camera;
}

Ray perspective_ray(const PerspectiveCamera& camera, int i, int j) {
    const double alpha = 2.0 * column_fraction(i, camera.width) - 1.0;
    const double beta = 2.0 * row_fraction(j, camera.height) - 1.0;
    const Frame& f = camera.frame;
    const Vec3 direction =
        normalize(alpha * camera.half_width * f.u + beta * camera.half_height * f.v - f.w);
    return {camera.eye, direction, 0.0, std::numeric_limits<double>::infinity()};
}

OrthographicCamera make_orthographic_camera(const Vec3& lookfrom, const Vec3& lookat,
                                            const Vec3& up, double left, double right,
                                            double bottom, double top, int width, int height) {
    // Written so that NaN fails; a finite width and height also rule out infinite edges, whose
    // rays would start at infinite or NaN points.
    if (!(left < right && bottom < top && std::isfinite(right - left) &&
          std::isfinite(top - bottom))) {
        throw std::domain_error(
            "camera: the orthographic window needs left < right and bottom < top, of finite width "
            "and height");
    }
    check_image_size(width, height);
    return {lookfrom, orthonormal_frame(lookfrom - lookat, up), left, right, bottom, top, width,
            height};
}

Ray orthographic_ray(const OrthographicCamera& camera, int i, int j) {
    const double x = camera.left + (camera.right - camera.left) * column_fraction(i, camera.width);
    const double y = camera.bottom + (camera.top - camera.bottom) * row_fraction(j, camera.height);
    const Frame& f = camera.frame;
    return {camera.eye + x * f.u + y * f.v, -f.w, 0.0, std::numeric_limits<double>::infinity()};
}

}  // namespace raystep
