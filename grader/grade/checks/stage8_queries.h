#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/protocol/probe_json.h"
#include "base/scene/scene.h"
#include "stages/2_rays/camera.h"

namespace raystep::grade {

// Stage 8's values as its probe calls take and give them (app/probe/sampling_calls.cpp), shared
// by the deterministic checks (stage8_checks.cpp) and the statistical ones
// (stage8_statistics.cpp).

probe::Json quad_light_json(const QuadLight& light);
probe::Json perspective_camera_json(const PerspectiveCamera& camera);
probe::Json orthographic_camera_json(const OrthographicCamera& camera);
probe::Json point_json(const Vec2& p);

/// A point [x, y] as a call answers it; throws (an unreadable answer) otherwise.
Vec2 point_from(const probe::Json& j);

/// Points [[x, y], ...] as a call answers them; throws (an unreadable answer) otherwise.
std::vector<Vec2> points_from(const probe::Json& j);

/// `count` stream numbers from `first` on: the streams one case asks for. Each case of a check
/// starts where the last one's streams end, so that no two cases share random numbers.
probe::Json stream_numbers(std::uint64_t first, int count);

/// `(x, y)` in full digits, for a report.
std::string point_text(const Vec2& p);

}  // namespace raystep::grade
