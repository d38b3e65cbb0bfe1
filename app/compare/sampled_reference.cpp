#include "app/compare/sampled_reference.h"

#include "renderer/render_pixel.h"

namespace raystep {

namespace fs = std::filesystem;

bool is_sampled_view(const Scene& scene, View view) {
    return averages_samples(view) && (scene.samples_per_pixel > 1 || !scene.quad_lights.empty());
}

fs::path tile_spread_path(const fs::path& reference_image) {
    return reference_image.parent_path() / (reference_image.stem().string() + ".spread.exr");
}

}  // namespace raystep
