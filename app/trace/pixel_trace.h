#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/trace/trace_comparison.h"
#include "base/scene/scene.h"
#include "renderer/view.h"

namespace raystep {

// One pixel's computation, for `raystep trace` and the trace panel of `raystep view`: both show
// the same lines and the same comparison, so what a student reads in the browser is what the
// command prints.

/// Every step of one pixel, one line each, as `raystep trace` prints them.
struct PixelTrace {
    std::vector<std::string> lines;
    bool stopped = false;  ///< a stub or an error ended it early; the last line says which
};

/// Traces pixel (x, y) of the view through the scene as it is (overrides applied). A stub or an
/// error on the way ends the trace with a "stopped" line rather than an exception. Throws
/// std::invalid_argument when the pixel is outside the image.
PixelTrace trace_pixel(const Scene& scene, View view, int x, int y);

/// This build's values of a pixel beside the reference's, from the scene's reference trace.
struct PixelComparison {
    std::filesystem::path reference_trace;  ///< the file the reference's values came from
    std::vector<std::string> notes;         ///< what was left out of the comparison, and why
    TraceComparison comparison;
    std::string stop;  ///< what stopped this build, when something did
};

/// Compares pixel (x, y) of the view with the reference's trace of the scene in `trace_file`: the
/// one a student release ships beside the scene file (reference_trace_path) unless another is
/// given. The scene must be as its file says: the reference recorded the scene's own ray offset
/// and samples. Throws InputError, naming the file and the problem, when there is no usable
/// reference trace: none there, a pixel outside the image, a scene changed since the trace was
/// written, a view that goes further than the trace.
PixelComparison compare_pixel_with_reference(const Scene& scene, View view, int x, int y,
                                             const std::filesystem::path& trace_file);

}  // namespace raystep
