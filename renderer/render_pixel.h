#pragma once

#include "base/image/image.h"
#include "base/math/types.h"
#include "renderer/pixel_observer.h"
#include "renderer/render_scene.h"
#include "renderer/view.h"

namespace raystep {

/// Pixel (i, j) of the view. Where the view averages samples and the scene has spp > 1, the
/// colour is stage 8's pixel_colour over the scene's samples per pixel, placed by its
/// `pixelsampling`, each sample a camera ray through its film point; else one camera ray through
/// the pixel's centre (stage 2's). Random numbers come from the streams of sample_streams.h, so
/// the pixel is the same whichever thread renders it. For the depth view the value is the hit's t
/// in every channel (infinity on a miss), and for the cost view the nodes visited plus primitives
/// tested, each turned into a colour by finish_view once the whole image is known; every other view
/// gives its final colour. Every step is told to `observer` as it is taken (pixel_observer.h).
Color render_pixel(const RenderScene& render_scene, View view, int i, int j,
                   PixelObserver& observer);
Color render_pixel(const RenderScene& render_scene, View view, int i, int j);

/// The part of a view that needs the whole image. Depth becomes inverse depth, t_near / t with
/// t_near the nearest positive hit distance in the image, so the nearest hit is white, a hit
/// twice as far is 0.5 grey, and an infinite plane fades to black at its horizon (a linear scale
/// would spend the whole grey range on that far plane); misses are black. Cost becomes a heat map
/// from black through blue, red and yellow to white at the image's most expensive pixel.
void finish_view(Image& image, View view);

}  // namespace raystep
