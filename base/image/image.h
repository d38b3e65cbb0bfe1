#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/math/types.h"

namespace raystep {

/// An RGB image in linear float, row 0 at the top, as image files store it.
class Image {
  public:
    Image() = default;
    Image(int width, int height)
        : width_(width), height_(height), rgb_(3 * pixel_count(width, height), 0.0f) {}

    int width() const { return width_; }
    int height() const { return height_; }

    /// Pixel (i, j): column i from the left, row j from the top. Throws std::out_of_range for a
    /// pixel outside the image (a texture lookup whose wrap_texel let an index out, stage 11).
    Color at(int i, int j) const {
        if (i < 0 || i >= width_ || j < 0 || j >= height_) {
            throw std::out_of_range("pixel (" + std::to_string(i) + ", " + std::to_string(j) +
                                    ") is outside the " + std::to_string(width_) + " x " +
                                    std::to_string(height_) + " image");
        }
        const std::size_t k = index(i, j);
        return {rgb_[k], rgb_[k + 1], rgb_[k + 2]};
    }

    void set(int i, int j, const Color& c) {
        const std::size_t k = index(i, j);
        rgb_[k] = static_cast<float>(c.r);
        rgb_[k + 1] = static_cast<float>(c.g);
        rgb_[k + 2] = static_cast<float>(c.b);
    }

    /// Interleaved RGB, row by row from the top: what OpenImageIO reads and writes.
    const float* data() const { return rgb_.data(); }
    float* data() { return rgb_.data(); }

  private:
    static std::size_t pixel_count(int width, int height) {
        return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    }
    std::size_t index(int i, int j) const {
        return 3 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(width_) +
                    static_cast<std::size_t>(i));
    }

    int width_ = 0;
    int height_ = 0;
    std::vector<float> rgb_;
};

}  // namespace raystep
