#include "app/compare/image_diff.h"

#include <cmath>
#include <limits>

#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "base/testing/filled_image.h"
#include "renderer/render_scene.h"
#include "renderer/tile_renderer.h"

using namespace raystep;
using raystep::compare_images;
using raystep::ImageDiff;
using raystep::testing::filled_image;

namespace {

// A render check's reference: the scene's view by the reference renderer, 160 pixels wide as the
// render checks make it (grader/grade/checks/render_checks.cpp).
Image reference_render(const std::string& scene_file, View view) {
    Scene scene = load_scene(std::filesystem::path(RAYSTEP_SOURCE_DIR) / "scenes" / scene_file);
    const double scale = 160.0 / scene.width;
    scene.width = 160;
    scene.height = static_cast<int>(std::lround(scene.height * scale));
    RenderOptions options;
    options.view = view;
    options.threads = 1;
    return render_image(prepare_render_scene(scene), options);
}

double share(std::size_t count, const ImageDiff& diff) {
    return static_cast<double>(count) / static_cast<double>(diff.pixels);
}

}  // namespace

TEST_CASE(
    "compare_images: an all-black render of the grey depth view differs visibly where "
    "the reference is lit",
    "[app]") {
    // The depth view of spheres on a plane: grey, from white on the nearest sphere to almost
    // black at the horizon. A student's all-black render must count as different wherever a
    // viewer sees grey.
    const Image reference = reference_render("stage3/spheres-on-plane.test", View::depth);
    const Image black = filled_image(reference.width(), reference.height(), Color(0.0));
    const ImageDiff diff = compare_images(reference, black, 0.02f);
    CAPTURE(diff.pixels, diff.pixels_over, diff.pixels_visibly_different);
    CHECK(share(diff.pixels_over, diff) == Approx(0.78).margin(0.03));
    // Grey over 0.033 (L* over 2.3, as sRGB) is visible; the few pixels from 0.02 to 0.033
    // are over idiff's threshold but darker than a viewer tells from black.
    CHECK(share(diff.pixels_visibly_different, diff) > 0.7);
    CHECK(diff.pixels_visibly_different <= diff.pixels_over);
    CHECK(share(diff.pixels_visibly_different, diff) >= 0.95 * share(diff.pixels_over, diff));
}

TEST_CASE("compare_images: a coloured render against black, and against itself", "[app]") {
    const Image reference = reference_render("stage6/cornell-box.test", View::shaded);
    const ImageDiff same = compare_images(reference, reference, 0.02f);
    CHECK(same.pixels_over == 0);
    CHECK(same.pixels_visibly_different == 0);
    const ImageDiff black = compare_images(
        reference, filled_image(reference.width(), reference.height(), Color(0.0)), 0.02f);
    CAPTURE(black.pixels_over, black.pixels_visibly_different);
    CHECK(share(black.pixels_visibly_different, black) > 0.6);
}

TEST_CASE("compare_images: a just noticeable difference, and NaN", "[app]") {
    const Image grey = filled_image(4, 4, Color(0.5));
    Image changed = grey;
    // Mid grey in sRGB is L* 53.4; 0.5 to 0.51 moves L* by 1.0, below notice, to 0.55 by 5.0.
    changed.set(0, 0, Color(0.51));
    changed.set(1, 0, Color(0.55));
    changed.set(2, 0, Color(0.5, 0.5, std::numeric_limits<double>::quiet_NaN()));
    const ImageDiff diff = compare_images(grey, changed, 0.02f);
    CHECK(diff.pixels_visibly_different == 2);
    CHECK(diff.pixels_over == 2);
    // Values past 1 show as 1: a brighter overexposure is not a visible difference.
    const ImageDiff clamped =
        compare_images(filled_image(4, 4, Color(1.0)), filled_image(4, 4, Color(3.0)), 0.02f);
    CHECK(clamped.pixels_visibly_different == 0);
    CHECK(clamped.pixels_over == 16);

    // The heat map shows a NaN in any channel at full scale.
    CHECK(difference_heat_map(grey, changed, 0.25f).at(2, 0) == Color(1.0));

    const ImageDiff wrong_size = compare_images(grey, filled_image(4, 3, Color(0.5)), 0.02f);
    CHECK_FALSE(wrong_size.same_size);
    CHECK(wrong_size.pixels_visibly_different == 16);
}
