#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "base/image/image.h"
#include "renderer/pixel_record.h"
#include "renderer/render_scene.h"
#include "renderer/view.h"

namespace raystep {

/// The pixels [x0, x1) x [y0, y1) of an image: one tile of a render.
struct TileRect {
    int x0, y0, x1, y1;
};

struct RenderOptions {
    View view = View::full;
    int threads = 0;                  ///< worker threads; 0 means one per hardware thread
    bool progress = false;            ///< draw a progress bar on stderr
    std::string label = "rendering";  ///< what the progress bar calls this render
    /// When given, filled with every pixel's record as it is rendered, row by row from the top
    /// (j * width + i): the values of its steps, which a reference trace stores.
    std::vector<PixelRecord>* records = nullptr;
    /// When given, called on a worker thread as each tile is done, with the image being rendered:
    /// for a render watched as it grows (`raystep view`). It may read only the tile it is given,
    /// whose pixels no thread writes again, and must be safe to call from several threads at once.
    std::function<void(const Image& image, const TileRect& tile)> on_tile;
    /// When given and set, no further tile is started; render_image returns once the tiles under
    /// way are done, with the rest of the image black.
    const std::atomic<bool>* cancel = nullptr;
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
