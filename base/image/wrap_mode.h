#pragma once

namespace raystep {

/// What a texture lookup beyond the image's edge reads (docs/stage11.md, "Wrapping"): the image
/// repeated, its edge texel, or the image repeated and mirrored at every edge.
enum class WrapMode { repeat, clamp, mirror };

}  // namespace raystep
