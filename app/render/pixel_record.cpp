#include "app/render/pixel_record.h"

#include "app/render/render_pixel.h"
#include "app/render/tile_renderer.h"

namespace raystep {

std::vector<PixelRecord> record_pixels(const RenderScene& render_scene, View view, int threads) {
    const int width = render_scene.scene->width;
    std::vector<PixelRecord> records(static_cast<std::size_t>(width) *
                                     static_cast<std::size_t>(render_scene.scene->height));
    // Each pixel writes only its own record, so the threads share nothing.
    render_pixels(
        width, render_scene.scene->height,
        [&](int i, int j) {
            PixelRecord& record = records[static_cast<std::size_t>(j) * width + i];
            return render_pixel(render_scene, view, i, j, nullptr, &record);
        },
        threads);
    return records;
}

}  // namespace raystep
