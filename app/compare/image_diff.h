#pragma once

#include <cstddef>
#include <filesystem>

#include "base/image/image.h"

namespace raystep {

/// How a student's render differs from the reference's, as idiff measures it, and as a viewer of
/// the report's images would see it. The perceptual count is a per-pixel colour difference, not
/// OpenImageIO's compare_Yee: in OpenImageIO 2.4 that metric fails no pixel of a grey image
/// against a black one (only differences of hue fail it), so that an all-black render of the
/// grey depth view counted 0 pixels where 78% differ.
struct ImageDiff {
    double mean_error = 0.0;  ///< mean absolute difference per channel
    double rms_error = 0.0;
    double psnr = 0.0;  ///< in dB; infinite for identical images
    double max_error = 0.0;
    std::size_t pixels = 0;
    std::size_t pixels_over = 0;  ///< pixels with a channel differing by more than `threshold`
    /// Pixels whose colours, as the report's 8-bit images show them, differ by more than a just
    /// noticeable difference (kJustNoticeableDeltaE); a NaN in either image is a difference.
    std::size_t pixels_visibly_different = 0;
    bool same_size = true;  ///< false: nothing else is meaningful
};

/// The CIE 1976 colour difference (Delta E*ab, the distance in L*a*b*) that a viewer just notices
/// side by side: about 2.3 (Mahy, Van Eycken and Oosterlinck 1994, Color Research and
/// Application 19(2); Sharma 2003, Digital Color Imaging Handbook, section 1.7).
constexpr double kJustNoticeableDeltaE = 2.3;

/// Compares two images of the same size; a different size is a difference of every pixel. Throws
/// std::runtime_error when the image library cannot be loaded (base/image/image_library_loader.h).
ImageDiff compare_images(const Image& reference, const Image& student, float threshold);

/// The difference as a heat map: black where the images agree, through red and yellow to white
/// where a channel differs by `full_scale` or more.
Image difference_heat_map(const Image& reference, const Image& student, float full_scale);

}  // namespace raystep
