#include "app/compare/render_rule.h"

#include "base/image/image_io.h"
#include "base/testing/catch.h"
#include "base/testing/filled_image.h"
#include "base/testing/scratch_folder.h"

using namespace raystep;
using raystep::testing::filled_image;

namespace {

// A 64 x 48 grey image (3072 pixels) with its first `count` pixels (row by row) 0.1 brighter.
Image with_brighter_pixels(int count) {
    Image image = filled_image(64, 48, Color(0.5));
    for (int k = 0; k < count; ++k)
        image.set(k % 64, k / 64, Color(0.6));
    return image;
}

}  // namespace

TEST_CASE("judge_render: 15 of 3072 pixels over the threshold pass, 16 fail", "[app]") {
    // 0.5% of 3072 is 15.36 pixels.
    const Image reference = filled_image(64, 48, Color(0.5));
    const RenderVerdict fifteen = judge_render(reference, with_brighter_pixels(15));
    CHECK(fifteen.diff.pixels_over == 15);
    CHECK(fifteen.passed);
    const RenderVerdict sixteen = judge_render(reference, with_brighter_pixels(16));
    CHECK(sixteen.diff.pixels_over == 16);
    CHECK_FALSE(sixteen.passed);
    CHECK(sixteen.share_over == Approx(16.0 / 3072.0));
}

TEST_CASE("judge_render: a pixel is over when a channel differs by more than 0.02", "[app]") {
    const Image reference = filled_image(4, 4, Color(0.25));
    const RenderVerdict within = judge_render(reference, filled_image(4, 4, Color(0.25 + 0.019)));
    CHECK(within.diff.pixels_over == 0);
    CHECK(within.passed);
    const RenderVerdict beyond = judge_render(reference, filled_image(4, 4, Color(0.25 + 0.021)));
    CHECK(beyond.diff.pixels_over == 16);
}

TEST_CASE("judge_render: an image of another size fails with every pixel over", "[app]") {
    const RenderVerdict verdict =
        judge_render(filled_image(64, 48, Color(0.5)), filled_image(32, 24, Color(0.5)));
    CHECK_FALSE(verdict.diff.same_size);
    CHECK_FALSE(verdict.passed);
    CHECK(verdict.share_over == 1.0);
    CHECK(render_summary(verdict) == "the image has the wrong size");
}

TEST_CASE("render_summary and render_metrics: the numbers the grader reports", "[app]") {
    const RenderVerdict verdict =
        judge_render(filled_image(64, 48, Color(0.5)), with_brighter_pixels(16));
    // RMSE over 3 channels of 3072 pixels, 16 of them off by 0.1: 0.1 * sqrt(16 / 3072).
    CHECK(render_summary(verdict) ==
          "16 of 3072 pixels differ by more than 0.02 (0.52%); RMSE 0.0072");
    const auto metrics = render_metrics(verdict.diff);
    REQUIRE(metrics.size() == 6);
    CHECK(metrics[0].first == "mean absolute error");
    CHECK(metrics[0].second == Approx(0.1 * 16 / 3072).epsilon(1e-5));
    CHECK(metrics[1].first == "rmse");
    CHECK(metrics[3] == std::pair<std::string, double>{"pixels over threshold", 16.0});
    CHECK(metrics[5] == std::pair<std::string, double>{"pixels", 3072.0});
}

TEST_CASE("judge_render_files: a PNG pair is judged as written, 8-bit rounding within the rule",
          "[app]") {
    const raystep::testing::ScratchFolder folder("render-rule");
    write_image(with_brighter_pixels(16), folder.path() / "image.png");
    write_image(filled_image(64, 48, Color(0.5)), folder.path() / "reference.png");
    const RenderFileVerdict judged =
        judge_render_files(folder.path() / "image.png", folder.path() / "reference.png");
    CHECK(judged.verdict.diff.pixels_over == 16);
    CHECK_FALSE(judged.verdict.passed);
    CHECK_THROWS_WITH(judge_render_files(folder.path() / "image.png", folder.path() / "none.png"),
                      Catch::Contains("none.png"));
}
