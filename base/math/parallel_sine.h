#pragma once

namespace raystep {

/// Two nonzero directions a and b count as parallel when |a x b| <= kParallelSine |a| |b|, that
/// is, when the sine of the angle between them is at most 1e-8.
///
/// Why 1e-8: a frame built from them, u = b x w / |b x w|, inherits the rounding of w (a few
/// ulps, about 1e-16 |b|) divided by |b x w|. At a sine of 1e-8 that moves u by at most ~1e-8
/// radians, far below what a pixel subtends (4e-4 radians for 4096 pixels across 90 degrees), so
/// a camera that passes this test is defined by its input and not by rounding; below it, it is
/// not, and the right answer is an error.
inline constexpr double kParallelSine = 1e-8;

}  // namespace raystep
