#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/pixel_record.h"
#include "renderer/view.h"

namespace raystep {

/// One quantity of a pixel's record, in the order of the pipeline.
enum class TraceQuantity {
    camera_origin,
    camera_direction,
    primitive,  ///< the closest hit's kind and index, or a miss
    t,
    normal,
    barycentrics,
    light_reach,
    light_term,
    local_colour,
    full_colour,
};

/// The mantissa bits a reference trace keeps of the quantity's values, each a float32 rounded to
/// nearest: 23 (all) for the quantities that are whole numbers (the primitive, a light's reach).
int stored_bits(TraceQuantity quantity);

/// The value as a reference trace stores it: a float32 rounded to nearest with stored_bits of
/// its mantissa kept.
double stored_value(double value, TraceQuantity quantity);

/// How far a stored value may be from the reference's own, relative to the quantity's
/// magnitude: 2^-24 for rounding it to a float32, and 2^-(stored_bits + 1) for keeping that many
/// bits of it; 0 for the quantities stored exactly (the primitive, a light's reach).
double stored_roundoff(TraceQuantity quantity);

/// The reference's values of every pixel of one scene, as a reference trace file holds them:
/// what `raystep trace --compare` holds a student's pixel against.
struct ReferenceTrace {
    int width = 0;
    int height = 0;
    View view = View::rays;  ///< the view it was recorded for: how far its records go
    std::size_t lights = 0;  ///< the scene's lights, each with its reach and term per pixel
    /// The digest of the scene's files as the reference rendered them (scene_digest); empty when
    /// the writer gave none.
    std::string scene_digest;
    std::vector<PixelRecord> pixels;  ///< row by row from the top, j * width + i

    /// Pixel (i, j), column i from the left and row j from the top.
    const PixelRecord& at(int i, int j) const {
        return pixels[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(i)];
    }
};

/// Writes the records of a width x height render of `view` (RenderOptions::records) as a
/// multi-channel OpenEXR image with ZIP compression, one channel a component ("hit.t",
/// "light0.term.R"): only the channels the view's reach fills, each value rounded to its
/// stored_bits and coded as reference_trace.cpp says, with `scene_digest`, the digest of the
/// scene's files (base/scene/scene_files.h). Throws std::runtime_error when it cannot write.
void write_reference_trace(const std::filesystem::path& path, int width, int height, View view,
                           std::size_t lights, const std::vector<PixelRecord>& pixels,
                           const std::string& scene_digest);

/// The file read back. Throws InputError naming the file and what is wrong when it cannot be
/// read (missing, truncated), is not a reference trace (another image, a channel missing) or
/// holds a value no record can have.
ReferenceTrace read_reference_trace(const std::filesystem::path& path);

}  // namespace raystep
