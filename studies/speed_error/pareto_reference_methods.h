#pragma once

#include <vector>

#include "studies/speed_error/pareto_study.h"

namespace raystep {

/// Every reference intersection test the study compares, in double and in float: the three
/// lecture triangle methods, Möller-Trumbore and the watertight test; the textbook sphere, the
/// stable roots with the plain discriminant, and the stable sphere (intersect_sphere); the plane
/// test. Linked only where solutions/ is.
std::vector<ParetoMethod> reference_pareto_methods();

}  // namespace raystep
