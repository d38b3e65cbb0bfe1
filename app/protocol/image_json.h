#pragma once

#include <cstddef>

#include "app/protocol/json_codec.h"
#include "app/protocol/probe_json.h"
#include "base/image/image.h"

namespace raystep::probe {

/// An image as {"width", "height", "rgb"}: its floats, little-endian, in base64. A 320 x 240
/// render is 1.2 MB of text this way, against about 3 MB as JSON numbers.
Json image(const Image& picture);

/// Throws (std::invalid_argument) when the size is not positive, is over `max_pixels`, or does
/// not match the data: an answer from the probe is never trusted.
Image image_from(const Json& j, std::size_t max_pixels);

/// An image as a call's argument or result. Read with a bound of kMaxArgumentPixels: the
/// grader's own questions (a stage-11 texture) are a few texels; an answer that may be large, a
/// render, is read by image_from with the bound its check sets.
inline constexpr std::size_t kMaxArgumentPixels = std::size_t{1} << 20;

template <>
struct JsonCodec<Image> {
    static Json write(const Image& picture) { return image(picture); }
    static Image read(const Json& j) { return image_from(j, kMaxArgumentPixels); }
};

}  // namespace raystep::probe
