#include "grader/protocol/image_json.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace raystep::probe {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64(const unsigned char* bytes, std::size_t size) {
    std::string text;
    text.reserve((size + 2) / 3 * 4);
    for (std::size_t k = 0; k < size; k += 3) {
        const std::uint32_t chunk = (std::uint32_t{bytes[k]} << 16) |
                                    (k + 1 < size ? std::uint32_t{bytes[k + 1]} << 8 : 0) |
                                    (k + 2 < size ? std::uint32_t{bytes[k + 2]} : 0);
        text += kAlphabet[(chunk >> 18) & 63];
        text += kAlphabet[(chunk >> 12) & 63];
        text += k + 1 < size ? kAlphabet[(chunk >> 6) & 63] : '=';
        text += k + 2 < size ? kAlphabet[chunk & 63] : '=';
    }
    return text;
}

int sextet(char c) {
    const char* found = std::strchr(kAlphabet, c);
    if (c == '\0' || !found) throw std::invalid_argument("not base64");
    return static_cast<int>(found - kAlphabet);
}

std::string unbase64(const std::string& text) {
    if (text.size() % 4 != 0) throw std::invalid_argument("base64 of a wrong length");
    std::string bytes;
    bytes.reserve(text.size() / 4 * 3);
    for (std::size_t k = 0; k < text.size(); k += 4) {
        const int pad = (text[k + 3] == '=') + (text[k + 2] == '=');
        std::uint32_t chunk = 0;
        for (int c = 0; c < 4; ++c) {
            chunk = (chunk << 6) | (c >= 4 - pad ? 0u : static_cast<std::uint32_t>(sextet(text[k + static_cast<std::size_t>(c)])));
        }
        bytes += static_cast<char>((chunk >> 16) & 255);
        if (pad < 2) bytes += static_cast<char>((chunk >> 8) & 255);
        if (pad < 1) bytes += static_cast<char>(chunk & 255);
    }
    return bytes;
}

}  // namespace

Json image(const Image& picture) {
    const std::size_t floats = 3 * static_cast<std::size_t>(picture.width()) *
                               static_cast<std::size_t>(picture.height());
    return {{"width", picture.width()},
            {"height", picture.height()},
            {"rgb", base64(reinterpret_cast<const unsigned char*>(picture.data()),
                           floats * sizeof(float))}};
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
    const std::size_t expected = 3 * static_cast<std::size_t>(width) *
                                 static_cast<std::size_t>(height) * sizeof(float);
    if (bytes.size() != expected) throw std::invalid_argument("image data of the wrong size");
    std::memcpy(picture.data(), bytes.data(), expected);
    return picture;
}

}  // namespace raystep::probe
