#pragma once

#include "app/check/ray_case.h"

namespace raystep {

/// Fills in every primitive's expectation with the exact oracle. With t_ulps above 0, each
/// expected t passes only within that many ulps of itself, instead of the rounding budget: a
/// family's way to check one accuracy requirement.
void decide_cases(CaseFamily& family, double t_ulps = 0.0);

}  // namespace raystep
