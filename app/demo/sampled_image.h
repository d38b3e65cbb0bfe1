#pragma once

#include "base/image/image.h"
#include "base/scene/scene.h"
#include "renderer/render_scene.h"

namespace raystep {

/// The full view of `render_scene` with `count` samples per pixel placed by `pattern`, every
/// pixel through stage 8's pixel_colour, at one sample too: the renderer takes the pixel's centre
/// at spp 1 whatever the pattern, while a single jittered or random sample is a random point of
/// the pixel, the first point of its curve in the sampling demo and study. Film points and light
/// samples come from the renderer's streams (renderer/sample_streams.h), so the image is the
/// same for any thread count; `threads` as render_pixels (0: one per hardware thread).
Image sampled_image(const RenderScene& render_scene, SamplePattern pattern, int count, int threads);

}  // namespace raystep
