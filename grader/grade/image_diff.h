#pragma once

#include <cstddef>
#include <filesystem>

#include "core/image/image.h"

namespace raystep::grade {

/// How a student's render differs from the reference's, as idiff measures it, and a perceptual
/// metric (Yee's, OpenImageIO's compare_Yee): pixels a viewer would see differ.
struct ImageDiff {
    double mean_error = 0.0;  ///< mean absolute difference per channel
    double rms_error = 0.0;
    double psnr = 0.0;        ///< in dB; infinite for identical images
    double max_error = 0.0;
    std::size_t pixels = 0;
    std::size_t pixels_over = 0;          ///< pixels with a channel differing by more than `threshold`
    std::size_t perceptual_failures = 0;  ///< pixels Yee's metric tells apart
    bool same_size = true;                ///< false: nothing else is meaningful
};

/// Compares two images of the same size; a different size is a difference of every pixel.
ImageDiff compare_images(const Image& reference, const Image& student, float threshold);

/// The difference as a heat map: black where the images agree, through red and yellow to white
/// where a channel differs by `full_scale` or more.
Image difference_heat_map(const Image& reference, const Image& student, float full_scale);

}  // namespace raystep::grade
