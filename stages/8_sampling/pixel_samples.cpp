// Stage 8: antialiasing. Handout: docs/stage8.md. Your stage-2 camera formula, at any point of
// the film instead of the pixel centre.

#include "base/errors/not_implemented.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

Ray perspective_ray_through(const PerspectiveCamera& camera, const Vec2& film) {
    // Stage 2 with (i + 0.5, j + 0.5) replaced by film = (x, y):
    //   alpha = 2 x / width - 1,   beta = 1 - 2 y / height,
    //   direction = normalize(alpha tan(fovx/2) u + beta tan(fovy/2) v - w).
    RAYSTEP_TODO(8, "perspective_ray_through", "Antialiasing");
}

Ray orthographic_ray_through(const OrthographicCamera& camera, const Vec2& film) {
    // Stage 2's window point at film = (x, y) instead of the pixel centre.
    RAYSTEP_TODO(8, "orthographic_ray_through", "Antialiasing");
}

Color pixel_colour(const FilmRadiance& radiance, int i, int j, SamplePattern pattern, int count,
                   RandomStream& random) {
    // The mean of radiance((i, j) + u) over the samples u = samples(pattern, count, random).
    RAYSTEP_TODO(8, "pixel_colour", "Antialiasing");
}

}  // namespace raystep
