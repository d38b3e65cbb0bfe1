#pragma once

#include <string>

#include "app/protocol/probe_json.h"
#include "base/image/image.h"
#include "renderer/view.h"

namespace raystep::grade {

// A render check's judge: the student's render against the reference's by the grader's rule
// (app/compare/render_rule.h), the reference rendered at the grader's size when the release was
// written and carried in the judge's data, every float as the grader holds it.

/// Where a render departs most from the reference's, as a report says it.
struct RenderPlace {
    std::string input;     ///< scene, view, the pixel in the render and in the scene's own size
    std::string expected;  ///< the reference's colour there
    std::string got;       ///< the student's
    std::string trace;     ///< `PROGRAM trace scenes/SCENE X Y --view VIEW` at the scene's size
};

/// The pixel whose largest channel differs most (a NaN first) between two images of one size,
/// rendered from scenes/`scene` (`scene_width` x `scene_height` at its own size) in `view`; the
/// trace command runs `program`.
RenderPlace worst_render_place(const std::string& scene, View view, int scene_width,
                               int scene_height, const Image& reference, const Image& student,
                               const std::string& program);

/// "render": the result an image judge_render passes against `reference`, the render of
/// scenes/`scene` in `view`, whose own size is `scene_width` x `scene_height`. Its verdict carries
/// the share of pixels that match as the check's fraction, the grader's summary line and, for a
/// render that fails, its worst pixel with the `raystep trace` of it.
probe::Json render_judge(const Image& reference, const std::string& scene, View view,
                         int scene_width, int scene_height);

/// The program a student's reproduce line runs, as the student README builds it.
inline constexpr const char* kStudentBuildRaystep = "build/student/bin/raystep";

}  // namespace raystep::grade
