#pragma once

#include <cstdint>

#include "base/math/random_stream.h"
#include "base/scene/scene.h"

namespace raystep {

// The random streams of a render (base/math/random_stream.h). Every stream is numbered from the
// pixel and the camera sample it serves, so a pixel's numbers depend on nothing else: not the
// thread that renders it, the tile order, or how many pixels came before.
//
// The numbering: pixel p = j * width + i is the high 32 bits, the low 32 bits say what the
// stream is for: 0 the film points of the pixel's samples (stage 8's pixel_colour), 1 + s the
// light samples of camera sample s, every quad light and every bounce of that sample drawing from
// it in turn. The loader keeps an image under 2^27 pixels and spp under 2^16, so neither half
// overflows into the other and no two streams of a render share a number.

/// What the stream of pixel (i, j) is for.
inline constexpr std::uint64_t kFilmStream = 0;

/// The number of the stream `use` of pixel (i, j): kFilmStream, or light_stream_use(s).
inline std::uint64_t pixel_stream(int width, int i, int j, std::uint64_t use) {
    const std::uint64_t pixel = static_cast<std::uint64_t>(j) * static_cast<std::uint64_t>(width) +
                                static_cast<std::uint64_t>(i);
    return (pixel << 32) | use;
}

/// What the stream of the light samples of camera sample `sample` (0 for a pixel's only ray) is
/// for.
inline std::uint64_t light_stream_use(int sample) {
    return 1 + static_cast<std::uint64_t>(sample);
}

/// The stream of the film points of pixel (i, j), seeded by the scene's `seed`.
inline RandomStream film_random(const Scene& scene, int i, int j) {
    return RandomStream(scene.seed, pixel_stream(scene.width, i, j, kFilmStream));
}

/// The stream of the light samples of camera sample `sample` of pixel (i, j).
inline RandomStream light_random(const Scene& scene, int i, int j, int sample) {
    return RandomStream(scene.seed, pixel_stream(scene.width, i, j, light_stream_use(sample)));
}

}  // namespace raystep
