#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/render/pixel_record.h"
#include "app/render/render_scene.h"
#include "app/render/view.h"
#include "base/image/image.h"

namespace raystep {

struct RenderOptions {
    View view = View::full;
    int threads = 0;                  ///< worker threads; 0 means one per hardware thread
    bool progress = false;            ///< draw a progress bar on stderr
    std::string label = "rendering";  ///< what the progress bar calls this render
    /// When given, filled with every pixel's record as it is rendered, row by row from the top
    /// (j * width + i): the values of its steps, which a reference trace stores.
    std::vector<PixelRecord>* records = nullptr;
};

/// The colour of pixel (i, j), column i from the left and row j from the top. It is called from
/// several threads at once, each time for another pixel.
using PixelFunction = std::function<Color(int i, int j)>;

/// Every pixel of a width x height image from `pixel`, in 16x16 tiles handed out to `threads`
/// threads (0: one per hardware thread), with no progress bar: for images that are not a view of
/// a scene (the lecture demos). Each pixel depends only on its own coordinates, so the image is
/// the same bit for bit for any thread count. The first exception a pixel throws stops the render
/// and is rethrown here.
Image render_pixels(int width, int height, const PixelFunction& pixel, int threads);

/// Renders every pixel of the view in 16x16 tiles handed out to a pool of threads. Each pixel
/// depends only on its own coordinates, so the image is the same bit for bit for any thread
/// count. The first exception a pixel throws (a NotImplemented stub, say) stops the render and
/// is rethrown here.
Image render_image(const RenderScene& render_scene, const RenderOptions& options);

}  // namespace raystep
