#pragma once

#include <cstdint>
#include <string>

#include "base/math/types.h"
#include "base/scene/scene.h"
#include "grader/grade/check_definition.h"

namespace raystep::grade {

// Where a render check looks from. A student release holds every scene's reference images, and
// nothing a submission's process returns is a witness, so a render the grader has to trust must be
// one that no release holds: each grade moves the scene's eye by angles drawn for that grade, and
// renders the reference from the same place. A right renderer renders any eye; an answer written
// in beforehand matches none.

/// How far the eye turns about the scene's look-at point: about the up direction by 4 to 8
/// degrees, either way, and towards or away from it by 2 to 4. Enough that the scene's own image
/// differs from the moved one in far more pixels than a render check allows (a grader test holds
/// every render check to that), small enough that the view still shows what the check is for.
inline constexpr double kEyeTurnMinDegrees = 4.0;
inline constexpr double kEyeTurnMaxDegrees = 8.0;
inline constexpr double kEyeTiltMinDegrees = 2.0;
inline constexpr double kEyeTiltMaxDegrees = 4.0;

/// The camera's eye turned about its look-at point, at the same distance from it, by angles drawn
/// from the grade's seed (GradingContext::eye_seed) and the check's id: each check looks from an
/// eye of its own, and `--check ID` reruns one from the same eye. The look-at point, the up hint
/// and the field of view stay.
Vec3 moved_eye(const CameraSpec& camera, std::uint64_t grade_seed, const std::string& check_id);

/// The context a render check runs in: `context` with its reproduce lines naming the grade's
/// `--eye-seed`, so that each reruns the check from the same eye.
GradingContext with_eye_seed(const GradingContext& context);

/// "seen from (x, y, z), not the scene's eye": what a report adds to a render check's input.
std::string moved_eye_text(const Vec3& eye);

/// " --lookfrom X Y Z", every number in the digits that read back as the same double: what a
/// student's `raystep render` or `raystep trace` command adds to render from the same eye.
std::string lookfrom_arguments(const Vec3& eye);

}  // namespace raystep::grade
