#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace raystep::grade {

// Images carried inside the report that shows them, so that one file holds everything: the
// student's HTML page, which is sent or uploaded alone, and PrairieLearn's results.json.

/// The image file as a data URL (RFC 2397), "data:image/png;base64,...", which an <img> or
/// PrairieLearn shows as it would the file. The media type comes from the extension: .png,
/// .jpg or .jpeg, .gif. nullopt when the file cannot be read, is larger than max_bytes, or has
/// another extension: the report then shows the image as missing.
std::optional<std::string> image_data_url(const std::filesystem::path& file, std::size_t max_bytes);

}  // namespace raystep::grade
