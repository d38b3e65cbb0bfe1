#pragma once

#include <string>

#include "core/image/image.h"
#include "core/render/render_scene.h"
#include "core/render/view.h"

namespace raystep {

struct RenderOptions {
    View view = View::full;
    int threads = 0;                  ///< worker threads; 0 means one per hardware thread
    bool progress = false;            ///< draw a progress bar on stderr
    std::string label = "rendering";  ///< what the progress bar calls this render
};

/// Renders every pixel of the view in 16x16 tiles handed out to a pool of threads. Each pixel
/// depends only on its own coordinates, so the image is the same bit for bit for any thread
/// count. The first exception a pixel throws (a NotImplemented stub, say) stops the render and
/// is rethrown here.
Image render_image(const RenderScene& render_scene, const RenderOptions& options);

}  // namespace raystep
