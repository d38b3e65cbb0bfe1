#include "app/trace/pixel_trace.h"

#include <stdexcept>

#include "app/compare/reference_trace.h"
#include "app/trace/trace_printer.h"
#include "base/errors/input_error.h"
#include "base/errors/not_implemented.h"
#include "base/math/to_text.h"
#include "base/scene/scene_files.h"
#include "renderer/pixel_record.h"
#include "renderer/render_pixel.h"
#include "renderer/render_scene.h"

namespace raystep {

namespace {

// The scene's lights as a trace names them, in the order shade_hit takes them.
std::vector<std::string> light_names(const Scene& scene) {
    std::vector<std::string> names;
    for (const PointLight& light : scene.point_lights)
        names.push_back(light_name("point", light.line));
    for (const DirectionalLight& light : scene.directional_lights)
        names.push_back(light_name("directional", light.line));
    return names;
}

// The reference's trace of the scene in `path`, checked against the scene as it is now.
ReferenceTrace reference_trace_for(const Scene& scene, View view,
                                   const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) {
        throw InputError(
            scene.path, 0,
            "no reference trace: the comparison reads " + path.string() +
                ", the reference's values of every pixel, which a student release ships for "
                "its own scenes. A scene of your own has none; the reference build writes one "
                "(`raystep-reference render SCENE --view full --trace-data " +
                path.string() + "` in the instructor's repository)");
    }
    ReferenceTrace trace = read_reference_trace(path);
    const std::string file = path.string();
    if (trace.width != scene.width || trace.height != scene.height) {
        throw InputError(file, 0,
                         "recorded for a " + std::to_string(trace.width) + " x " +
                             std::to_string(trace.height) + " image, but " + scene.path + " is " +
                             std::to_string(scene.width) + " x " + std::to_string(scene.height) +
                             ": the scene changed since then");
    }
    const std::size_t lights = scene.point_lights.size() + scene.directional_lights.size();
    if (pipeline_reach(trace.view) >= PipelineReach::shading && trace.lights != lights) {
        throw InputError(file, 0,
                         "recorded for " + std::to_string(trace.lights) + " lights, but " +
                             scene.path + " has " + std::to_string(lights) +
                             ": the scene changed since then");
    }
    if (pipeline_reach(view) > pipeline_reach(trace.view)) {
        throw InputError(file, 0,
                         "it holds the reference's steps as far as the " +
                             std::string(view_name(trace.view)) + " view takes them; the " +
                             std::string(view_name(view)) + " view goes further: compare the " +
                             std::string(view_name(trace.view)) + " view or a view before it");
    }
    return trace;
}

}  // namespace

PixelTrace trace_pixel(const Scene& scene, View view, int x, int y) {
    if (x < 0 || x >= scene.width || y < 0 || y >= scene.height) {
        throw std::invalid_argument("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                    ") is outside the " + std::to_string(scene.width) + " x " +
                                    std::to_string(scene.height) + " image of " + scene.path);
    }
    PixelTrace trace;
    std::vector<std::string>& lines = trace.lines;
    lines.push_back("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") of " +
                    scene.path + ", view " + std::string(view_name(view)));
    try {
        const RenderScene render_scene = prepare_render_scene(scene);
        TracePrinter printer(render_scene, lines);
        const Color value = render_pixel(render_scene, view, x, y, printer);
        lines.push_back("value: " + to_text(value) +
                        (view == View::depth ? " (t; the image scales it to grey)" : ""));
    } catch (const NotImplemented& stub) {
        lines.push_back(std::string("stopped: ") + stub.what());
        trace.stopped = true;
    } catch (const std::exception& error) {
        lines.push_back(std::string("stopped by an error: ") + error.what());
        trace.stopped = true;
    }
    return trace;
}

PixelComparison compare_pixel_with_reference(const Scene& scene, View view, int x, int y,
                                             const std::filesystem::path& trace_file) {
    if (x < 0 || x >= scene.width || y < 0 || y >= scene.height) {
        throw InputError(scene.path, 0,
                         "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                             ") is outside its " + std::to_string(scene.width) + " x " +
                             std::to_string(scene.height) + " image");
    }
    const ReferenceTrace reference = reference_trace_for(scene, view, trace_file);

    PixelComparison result;
    result.reference_trace = trace_file;
    // A scene edited since the reference traced it keeps its size and lights (else
    // reference_trace_for refused it) but not its values: a difference may be the edit's.
    if (!reference.scene_digest.empty() && reference.scene_digest != scene_digest(scene)) {
        result.notes.push_back(
            "the scene's files changed since the reference traced them: its values are of the "
            "scene as it was, so a difference may come from the edit, not from your code");
    }
    PixelRecord ours;
    try {
        const RenderScene render_scene = prepare_render_scene(scene);
        PixelRecorder recorder(ours, scene.dialect);
        render_pixel(render_scene, view, x, y, recorder);
    } catch (const std::exception& error) {
        result.stop = error.what();
    }
    // A sampled pixel's samples may come in any order, so no sample of this build need be the
    // reference's first: both records hold the centre ray (render_pixel.h), and what a quad
    // light's random samples decide is left out.
    const bool random_colours = averages_samples(view) && !scene.quad_lights.empty();
    if (averages_samples(view) && scene.samples_per_pixel > 1) {
        result.notes.push_back(
            "sampled pixel: compared the ray through the pixel's centre, as "
            "at spp 1; the pixel's " +
            std::to_string(scene.samples_per_pixel) +
            " samples, which may come in any order, are not compared");
    }
    if (random_colours) {
        result.notes.push_back(
            "quad light: compared up to the other lights; the local and full colours hold its "
            "random light samples and are not compared (raystep compare judges them)");
    }
    result.comparison =
        compare_pixel(ours, reference.at(x, y), view, light_names(scene), random_colours);
    // An error after the last step the view takes (none do today) still stops the trace.
    result.comparison.stopped = result.comparison.stopped || !result.stop.empty();
    return result;
}

}  // namespace raystep
