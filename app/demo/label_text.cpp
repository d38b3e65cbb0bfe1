#include "app/demo/label_text.h"

#include <array>
#include <stdexcept>
#include <string>

#include "base/image/image_library_loader.h"

namespace raystep {

namespace {

// Paths first, where distributions put DejaVu Sans (Debian and Ubuntu, Fedora, Arch); then names
// that OpenImageIO looks up in the usual font folders (/Library/Fonts, C:/Windows/Fonts, ...).
constexpr std::array<const char*, 7> kFonts = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "DejaVuSans",
    "/System/Library/Fonts/Supplemental/Arial.ttf",
    "Arial",
    "Verdana",
};

// The smallest size a label shrinks to before it is drawn cut off: below it nobody reads it.
constexpr int kSmallestTextSize = 9;

// True when OpenImageIO can open the font.
bool can_open(const char* font) {
    int width = 0;
    return image_library().text_width("M", 12, font, &width) == nullptr;
}

// The width of the text drawn `size` pixels high with the font.
int text_width(const std::string& text, int size, const LabelFont& font) {
    int width = 0;
    throw_on_image_failure(
        image_library().text_width(text.c_str(), size, font.name.c_str(), &width),
        "cannot draw the label '" + text + "': ");
    return width;
}

}  // namespace

std::optional<LabelFont> find_label_font() {
    for (const char* font : kFonts) {
        if (can_open(font)) return LabelFont{font};
    }
    return std::nullopt;
}

std::string label_fonts_tried() {
    std::string list;
    for (const char* font : kFonts) {
        if (!list.empty()) list += ", ";
        list += font;
    }
    return list;
}

std::string thousands(std::uint64_t count) {
    std::string digits = std::to_string(count);
    for (int k = static_cast<int>(digits.size()) - 3; k > 0; k -= 3) {
        digits.insert(static_cast<std::size_t>(k), ",");
    }
    return digits;
}

void draw_text(Image& image, const LabelFont& font, std::string_view text, int x, int y, int size,
               int max_width, TextAlign align, const Color& colour) {
    for (const char c : text) {
        if (static_cast<unsigned char>(c) > 127) {
            throw std::invalid_argument("label '" + std::string(text) +
                                        "': OpenImageIO 2.4 draws only ASCII correctly");
        }
    }

    // Shrink until the text fits
    const std::string line(text);
    int fitted = size;
    while (fitted > kSmallestTextSize && text_width(line, fitted, font) > max_width)
        --fitted;

    // Draw straight into the image's pixels
    const float rgb[3] = {static_cast<float>(colour.r), static_cast<float>(colour.g),
                          static_cast<float>(colour.b)};
    throw_on_image_failure(
        image_library().draw_text(image.data(), image.width(), image.height(), x, y, line.c_str(),
                                  fitted, font.name.c_str(), rgb, align == TextAlign::centre),
        "cannot draw the label '" + line + "' with " + font.name + ": ");
}

}  // namespace raystep
