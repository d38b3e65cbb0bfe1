#include "app/compare/image_diff.h"

#include <algorithm>
#include <cmath>

#include "base/image/image_library_loader.h"

namespace raystep {

namespace {

// The largest of a pixel's channel differences; NaN when any channel's is (std::max would drop
// a NaN that is not first).
double largest_difference(const Color& reference, const Color& student) {
    const Color d = glm::abs(reference - student);
    if (std::isnan(d.r) || std::isnan(d.g) || std::isnan(d.b)) return std::nan("");
    return std::max({d.r, d.g, d.b});
}

struct Lab {
    double l = 0.0;
    double a = 0.0;
    double b = 0.0;
};

// The sRGB transfer function's inverse (IEC 61966-2-1): an encoded value in [0, 1] to linear.
double srgb_decoded(double value) {
    return value <= 0.04045 ? value / 12.92 : std::pow((value + 0.055) / 1.055, 2.4);
}

// CIE L*a*b*'s compression of a ratio to the white point's (CIE 15:2004, section 8.2.1).
double lab_f(double ratio) {
    constexpr double kDelta = 6.0 / 29.0;
    return ratio > kDelta * kDelta * kDelta ? std::cbrt(ratio)
                                            : ratio / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}

// The colour a viewer sees for a pixel of the report's images: write_image stores each channel
// clamped to [0, 1] with no gamma curve, and a browser shows the 8-bit values as sRGB. Linear
// sRGB to XYZ and the D65 white are IEC 61966-2-1's. A NaN channel stays NaN (std::clamp passes
// it through), so that its difference is NaN.
Lab displayed_lab(const Color& pixel) {
    const double r = srgb_decoded(std::clamp(pixel.r, 0.0, 1.0));
    const double g = srgb_decoded(std::clamp(pixel.g, 0.0, 1.0));
    const double b = srgb_decoded(std::clamp(pixel.b, 0.0, 1.0));
    const double x = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
    const double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
    const double z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
    const double fx = lab_f(x / 0.95047);
    const double fy = lab_f(y / 1.0);
    const double fz = lab_f(z / 1.08883);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// CIE 1976 Delta E*ab: the distance between two colours in L*a*b*.
double delta_e(const Lab& p, const Lab& q) {
    return std::sqrt((p.l - q.l) * (p.l - q.l) + (p.a - q.a) * (p.a - q.a) +
                     (p.b - q.b) * (p.b - q.b));
}

}  // namespace

ImageDiff compare_images(const Image& reference, const Image& student, float threshold) {
    ImageDiff diff;
    diff.pixels =
        static_cast<std::size_t>(reference.width()) * static_cast<std::size_t>(reference.height());
    if (reference.width() != student.width() || reference.height() != student.height()) {
        diff.same_size = false;
        diff.pixels_over = diff.pixels;
        diff.pixels_visibly_different = diff.pixels;
        diff.mean_error = diff.rms_error = diff.max_error = HUGE_VAL;
        return diff;
    }
    RaystepImageComparison numbers{};
    throw_on_image_failure(
        image_library().compare_rgb(reference.width(), reference.height(), reference.data(),
                                    student.data(), threshold, &numbers),
        "");
    diff.mean_error = numbers.mean_error;
    diff.rms_error = numbers.rms_error;
    diff.psnr = numbers.psnr;
    diff.max_error = numbers.max_error;
    // compare counts channel values; a pixel is over when any of its channels is. A NaN in the
    // student's image is a difference, whatever the threshold: both tests are written to count
    // a NaN.
    for (int j = 0; j < reference.height(); ++j) {
        for (int i = 0; i < reference.width(); ++i) {
            if (!(largest_difference(reference.at(i, j), student.at(i, j)) <= threshold)) {
                ++diff.pixels_over;
            }
            const double seen =
                delta_e(displayed_lab(reference.at(i, j)), displayed_lab(student.at(i, j)));
            if (!(seen <= kJustNoticeableDeltaE)) ++diff.pixels_visibly_different;
        }
    }
    return diff;
}

Image difference_heat_map(const Image& reference, const Image& student, float full_scale) {
    Image heat(reference.width(), reference.height());
    if (reference.width() != student.width() || reference.height() != student.height()) {
        for (int j = 0; j < heat.height(); ++j) {
            for (int i = 0; i < heat.width(); ++i)
                heat.set(i, j, Color(1.0));
        }
        return heat;
    }
    for (int j = 0; j < heat.height(); ++j) {
        for (int i = 0; i < heat.width(); ++i) {
            const double largest = largest_difference(reference.at(i, j), student.at(i, j));
            const double x = std::isnan(largest) ? 1.0 : std::min(1.0, largest / full_scale);
            // Black, red, yellow, white: each third of the scale brings in one channel.
            heat.set(i, j,
                     {std::min(1.0, 3 * x), std::clamp(3 * x - 1, 0.0, 1.0),
                      std::clamp(3 * x - 2, 0.0, 1.0)});
        }
    }
    return heat;
}

}  // namespace raystep
