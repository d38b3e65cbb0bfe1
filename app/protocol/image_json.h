#pragma once

#include "app/protocol/probe_json.h"
#include "base/image/image.h"

namespace raystep::probe {

/// An image as {"width", "height", "rgb"}: its floats, little-endian, in base64. A 320 x 240
/// render is 1.2 MB of text this way, against about 3 MB as JSON numbers.
Json image(const Image& picture);

/// Throws (std::invalid_argument) when the size is not positive, is over `max_pixels`, or does
/// not match the data: an answer from the probe is never trusted.
Image image_from(const Json& j, std::size_t max_pixels);

}  // namespace raystep::probe
