// Stage 8: rays through any point of a pixel, and the pixel's mean. Handout: docs/stage8.md.

#include <limits>

#include "stages/1_vectors/vectors.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

Ray perspective_ray_through(const PerspectiveCamera& camera, const Vec2& film) {
    // Stage 2's formula with the pixel centre (i + 0.5, j + 0.5) replaced by any film point.
    const double alpha = 2.0 * film.x / camera.width - 1.0;
    const double beta = 1.0 - 2.0 * film.y / camera.height;
    const Frame& f = camera.frame;
    const Vec3 direction =
        normalize(alpha * camera.half_width * f.u + beta * camera.half_height * f.v - f.w);
    return {camera.eye, direction, 0.0, std::numeric_limits<double>::infinity()};
}

Ray orthographic_ray_through(const OrthographicCamera& camera, const Vec2& film) {
    const double x = camera.left + (camera.right - camera.left) * (film.x / camera.width);
    const double y = camera.bottom + (camera.top - camera.bottom) * (1.0 - film.y / camera.height);
    const Frame& f = camera.frame;
    return {camera.eye + x * f.u + y * f.v, -f.w, 0.0, std::numeric_limits<double>::infinity()};
}

Color pixel_colour(const FilmRadiance& radiance, int i, int j, SamplePattern pattern, int count,
                   RandomStream& random) {
    Color sum(0.0);
    for (const Vec2& u : samples(pattern, count, random))
        sum += radiance(Vec2(i, j) + u);
    return sum / static_cast<double>(count);
}

}  // namespace raystep
