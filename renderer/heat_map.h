#pragma once

#include "base/math/types.h"

namespace raystep {

/// The colour of a heat map at `fraction` of its range: black (0) through blue, red and yellow to
/// white (1), with stops spread so that equal steps of the value are visible steps of colour.
/// Fractions outside [0, 1] are clamped. The cost view and the cost demos draw with it.
Color heat_colour(double fraction);

}  // namespace raystep
