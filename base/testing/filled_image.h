#pragma once

#include "base/image/image.h"

namespace raystep::testing {

/// A width x height image of one colour, for tests that compare or lay out images.
inline Image filled_image(int width, int height, const Color& colour) {
    Image image(width, height);
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i)
            image.set(i, j, colour);
    }
    return image;
}

}  // namespace raystep::testing
