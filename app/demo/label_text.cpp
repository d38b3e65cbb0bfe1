#include "app/demo/label_text.h"

#include <array>
#include <stdexcept>
#include <string>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

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

// True when OpenImageIO can open the font; a failed attempt leaves an error message in
// OpenImageIO, taken here so that it is not printed later.
bool can_open(const char* font) {
    if (OIIO::ImageBufAlgo::text_size("M", 12, font).defined()) return true;
    OIIO::geterror();
    return false;
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
    int fitted = size;
    while (fitted > kSmallestTextSize &&
           OIIO::ImageBufAlgo::text_size(text, fitted, font.name).width() > max_width) {
        --fitted;
    }

    // Draw straight into the image's pixels: an ImageBuf over our buffer copies nothing
    const OIIO::ImageSpec spec(image.width(), image.height(), 3, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf buffer(spec, image.data());
    const float rgb[3] = {static_cast<float>(colour.r), static_cast<float>(colour.g),
                          static_cast<float>(colour.b)};
    const auto align_x = align == TextAlign::centre ? OIIO::ImageBufAlgo::TextAlignX::Center
                                                    : OIIO::ImageBufAlgo::TextAlignX::Left;
    if (!OIIO::ImageBufAlgo::render_text(buffer, x, y, text, fitted, font.name, rgb, align_x,
                                         OIIO::ImageBufAlgo::TextAlignY::Center)) {
        throw std::runtime_error("cannot draw the label '" + std::string(text) + "' with " +
                                 font.name + ": " + buffer.geterror());
    }
}

}  // namespace raystep
