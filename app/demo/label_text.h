#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "base/image/image.h"

namespace raystep {

// Text on the demos' images, drawn by OpenImageIO with a TrueType font. OpenImageIO has no font
// of its own on every platform (Debian's build has none), so the font is looked for by path and
// by name; without one a demo still writes its image, unlabelled.

/// A font OpenImageIO can draw with: a file path, or a name it finds in the system's font folders.
struct LabelFont {
    std::string name;
};

/// The first font of the list below that OpenImageIO can open: DejaVu Sans by its paths on Linux
/// distributions (Debian's fonts-dejavu-core), then names that OpenImageIO finds in the font
/// folders of macOS and Windows. nullopt when none opens; std::runtime_error when the image
/// library cannot be loaded (base/image/image_library_loader.h).
std::optional<LabelFont> find_label_font();

/// The fonts find_label_font tries, comma-separated, for the message when none is found.
std::string label_fonts_tried();

/// "12,345": a count as the labels print it.
std::string thousands(std::uint64_t count);

enum class TextAlign { left, centre };

/// Draws one line of ASCII text in `colour`, vertically centred on row y, starting at column x
/// (left) or centred on it, `size` pixels high, or smaller when that is what it takes to fit in
/// `max_width` pixels. Pixels outside the image are skipped. Throws std::invalid_argument for
/// text beyond ASCII (OpenImageIO 2.4, Debian 12's, draws an epsilon as '5': it keeps only the
/// last 6 bits of a multi-byte UTF-8 character), std::runtime_error when OpenImageIO cannot
/// draw it.
void draw_text(Image& image, const LabelFont& font, std::string_view text, int x, int y, int size,
               int max_width, TextAlign align, const Color& colour = Color(1.0));

}  // namespace raystep
