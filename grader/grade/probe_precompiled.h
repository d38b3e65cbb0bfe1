// What a submission's stage files include from outside raystep, compiled once per build of the
// grader into a precompiled header (grader/CMakeLists.txt), which every compile of a submission's
// file takes first (`-include`), so that a grade does not parse these again for each file:
// parsing was four fifths of those compiles (docs/measurements/grading-time.md). Only headers
// guarded by macros of their own: raystep's headers are the submission's copy's to include, by
// their own paths, and GLM's experimental extensions need a macro a file may not define.
//
// Where the precompiled header does not fit a compile (flags it was not made with), GCC reads this
// file as text instead: slower, and the same program. No `#pragma once`: the file is compiled on
// its own, where GCC warns of one, and included once, first.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
