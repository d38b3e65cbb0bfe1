#pragma once

namespace raystep {

/// The unit roundoff of a double, u = 2^-53: one rounding to nearest changes a value by at most
/// u of its size (half an ulp of 1). Error bounds and the grader's tolerances count in it.
inline constexpr double kUnitRoundoff = 0x1p-53;

}  // namespace raystep
