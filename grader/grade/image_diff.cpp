#include "grader/grade/image_diff.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

namespace raystep::grade {

namespace {

OIIO::ImageBuf buffer(const Image& image) {
    OIIO::ImageBuf buf(OIIO::ImageSpec(image.width(), image.height(), 3, OIIO::TypeDesc::FLOAT));
    buf.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, image.data());
    return buf;
}

}  // namespace

ImageDiff compare_images(const Image& reference, const Image& student, float threshold) {
    ImageDiff diff;
    diff.pixels = static_cast<std::size_t>(reference.width()) * static_cast<std::size_t>(reference.height());
    if (reference.width() != student.width() || reference.height() != student.height()) {
        diff.same_size = false;
        diff.pixels_over = diff.pixels;
        diff.perceptual_failures = diff.pixels;
        diff.mean_error = diff.rms_error = diff.max_error = HUGE_VAL;
        return diff;
    }
    const OIIO::ImageBuf a = buffer(reference);
    const OIIO::ImageBuf b = buffer(student);
    const OIIO::ImageBufAlgo::CompareResults numbers =
        OIIO::ImageBufAlgo::compare(a, b, threshold, threshold);
    diff.mean_error = numbers.meanerror;
    diff.rms_error = numbers.rms_error;
    diff.psnr = numbers.PSNR;
    diff.max_error = numbers.maxerror;
    // compare counts channel values; a pixel is over when any of its channels is.
    for (int j = 0; j < reference.height(); ++j) {
        for (int i = 0; i < reference.width(); ++i) {
            const Color d = glm::abs(reference.at(i, j) - student.at(i, j));
            // A NaN in the student's image is a difference, whatever the threshold.
            if (!(std::max({d.r, d.g, d.b}) <= threshold)) ++diff.pixels_over;
        }
    }
    OIIO::ImageBufAlgo::CompareResults perceptual;
    diff.perceptual_failures =
        static_cast<std::size_t>(OIIO::ImageBufAlgo::compare_Yee(a, b, perceptual));
    return diff;
}

Image difference_heat_map(const Image& reference, const Image& student, float full_scale) {
    Image heat(reference.width(), reference.height());
    if (reference.width() != student.width() || reference.height() != student.height()) {
        for (int j = 0; j < heat.height(); ++j) {
            for (int i = 0; i < heat.width(); ++i) heat.set(i, j, Color(1.0));
        }
        return heat;
    }
    for (int j = 0; j < heat.height(); ++j) {
        for (int i = 0; i < heat.width(); ++i) {
            const Color d = glm::abs(reference.at(i, j) - student.at(i, j));
            const double largest = std::max({d.r, d.g, d.b});
            const double x = std::isnan(largest) ? 1.0 : std::min(1.0, largest / full_scale);
            // Black, red, yellow, white: each third of the scale brings in one channel.
            heat.set(i, j, {std::min(1.0, 3 * x), std::clamp(3 * x - 1, 0.0, 1.0),
                            std::clamp(3 * x - 2, 0.0, 1.0)});
        }
    }
    return heat;
}

}  // namespace raystep::grade
