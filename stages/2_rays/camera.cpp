// Stage 2: cameras. Handout: docs/stage2.md. Use your stage-1 functions (orthonormal_frame,
// normalize) here.

#include "stages/2_rays/camera.h"

#include <cmath>
#include <stdexcept>

#include "base/errors/not_implemented.h"

namespace raystep {

PerspectiveCamera make_perspective_camera(const Vec3& lookfrom, const Vec3& lookat, const Vec3& up,
                                          double fovy_degrees, int width, int height) {
    // Check the arguments (throw std::domain_error), then:
    //   frame       = orthonormal_frame(lookfrom - lookat, up)
    //   half_height = tan(fovy / 2), with fovy in radians
    //   half_width  = half_height * width / height
    RAYSTEP_TODO(2, "make_perspective_camera", "The perspective camera");
}

Ray perspective_ray(const PerspectiveCamera& camera, int i, int j) {
    // Map the pixel centre (i + 0.5, j + 0.5) to alpha in [-1, 1] (left to right) and beta in
    // [-1, 1] (bottom to top; row 0 is the top), then
    //   direction = normalize(alpha half_width u + beta half_height v - w).
    RAYSTEP_TODO(2, "perspective_ray", "Rays through pixel centres");
}

OrthographicCamera make_orthographic_camera(const Vec3& lookfrom, const Vec3& lookat,
                                            const Vec3& up, double left, double right,
                                            double bottom, double top, int width, int height) {
    // Check the arguments (throw std::domain_error, NaN and infinite window edges too), then keep
    // the frame and the window.
    RAYSTEP_TODO(2, "make_orthographic_camera", "The orthographic camera");
}

Ray orthographic_ray(const OrthographicCamera& camera, int i, int j) {
    // The pixel centre maps to x in [left, right] and y in [top, bottom]; the ray starts at
    // eye + x u + y v and goes along -w.
    RAYSTEP_TODO(2, "orthographic_ray", "The orthographic camera");
}

}  // namespace raystep
