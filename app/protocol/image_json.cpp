#include "app/protocol/image_json.h"

#include <cstring>
#include <stdexcept>
#include <string>

#include "app/protocol/base64.h"

namespace raystep::probe {

Json image(const Image& picture) {
    const std::size_t floats =
        3 * static_cast<std::size_t>(picture.width()) * static_cast<std::size_t>(picture.height());
    return {{"width", picture.width()},
            {"height", picture.height()},
            {"rgb", base64(std::string_view(reinterpret_cast<const char*>(picture.data()),
                                            floats * sizeof(float)))}};
}

Image image_from(const Json& j, std::size_t max_pixels) {
    const int width = j.at("width").get<int>();
    const int height = j.at("height").get<int>();
    if (width <= 0 || height <= 0 ||
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) > max_pixels) {
        throw std::invalid_argument("an image of " + std::to_string(width) + " x " +
                                    std::to_string(height) + " pixels");
    }
    const std::string bytes = unbase64(j.at("rgb").get<std::string>());
    Image picture(width, height);
    const std::size_t expected =
        3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * sizeof(float);
    if (bytes.size() != expected) throw std::invalid_argument("image data of the wrong size");
    std::memcpy(picture.data(), bytes.data(), expected);
    return picture;
}

}  // namespace raystep::probe
