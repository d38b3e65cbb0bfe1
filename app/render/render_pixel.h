#pragma once

#include "app/render/pixel_record.h"
#include "app/render/render_scene.h"
#include "app/render/trace_log.h"
#include "app/render/view.h"
#include "base/image/image.h"
#include "base/math/types.h"

namespace raystep {

/// Pixel (i, j) of the view. For the depth view the value is the hit's t in every channel
/// (infinity on a miss), and for the cost view the nodes visited plus primitives tested, each
/// turned into a colour by finish_view once the whole image is known; every
/// other view gives its final colour. When `trace` is given, every step is added to it: the
/// camera ray, each primitive tested and its result, and the closest hit. When `record` is given,
/// the values of the steps the view takes are put in it as they are computed.
Color render_pixel(const RenderScene& render_scene, View view, int i, int j, TraceLog* trace,
                   PixelRecord* record);

/// The part of a view that needs the whole image. Depth becomes inverse depth, t_near / t with
/// t_near the nearest positive hit distance in the image, so the nearest hit is white, a hit
/// twice as far is 0.5 grey, and an infinite plane fades to black at its horizon (a linear scale
/// would spend the whole grey range on that far plane); misses are black. Cost becomes a heat map
/// from black through blue, red and yellow to white at the image's most expensive pixel.
void finish_view(Image& image, View view);

}  // namespace raystep
