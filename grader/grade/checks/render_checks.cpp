// Render checks: a scene's view as the submission renders it, diffed with the same view from the
// reference, rendered here in the grader from the same eye, which each grade moves (moved_eye.h):
// a release holds the reference's images from the scene's own eye (render_public_checks), and
// the grader never asks for one of those. Each stage is graded on the view that shows its work
// (ARCHITECTURE.md, "Checks per stage"), with every other stage from the reference; the pipeline
// checks render with every stage from the submission.

#include <cmath>
#include <filesystem>

#include "app/compare/render_rule.h"
#include "app/grade/render_judge.h"
#include "app/probe/render_calls.h"
#include "app/protocol/image_json.h"
#include "base/image/image_io.h"
#include "base/scene/scene_loader.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/moved_eye.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/4_accel/stage4_cases.h"
#include "renderer/tile_renderer.h"

namespace raystep::grade {

namespace {

namespace fs = std::filesystem;

Scene scaled_scene(const fs::path& path) {
    Scene scene = load_scene(path);
    if (scene.width > kRenderCheckWidth) {
        const double scale = static_cast<double>(kRenderCheckWidth) / scene.width;
        scene.width = kRenderCheckWidth;
        scene.height = std::max(1, static_cast<int>(std::lround(scene.height * scale)));
    }
    return scene;
}

// The part of each camera ray a render looks at: all of it, or a near and a far clip that a
// structure must keep to (stage 2's rays start at 0 and never end).
struct CameraClip {
    double t_min = 0.0;
    double t_max = HUGE_VAL;
    std::string name;  ///< added to the check's id; empty for no clip
};

// The reference's render of the view, from `eye` where one is given.
Image reference_render(const fs::path& path, View view, const CameraClip& clip,
                       const std::optional<Vec3>& eye) {
    Scene scene = scaled_scene(path);
    if (eye) scene.camera.lookfrom = *eye;
    RenderOptions options;
    options.view = view;
    options.threads = 1;
    RenderScene render_scene = prepare_render_scene(scene);
    render_scene.camera_t_min = clip.t_min;
    render_scene.camera_t_max = clip.t_max;
    return render_image(render_scene, options);
}

// The student's own render of the view, from `eye` where one is given.
std::string render_command(const std::string& scene, View view, const std::optional<Vec3>& eye) {
    return std::string(kStudentRaystep) + " render scenes/" + scene + " --view " +
           std::string(view_name(view)) + (eye ? lookfrom_arguments(*eye) : "");
}

// The render's worst pixel as a counterexample (worst_render_place, app/grade/render_judge.h,
// which a release's `raystep grade` reports the same way): the colours, and the `raystep trace` of
// the same place in the scene at its own size (the grader renders at most kRenderCheckWidth wide)
// and from the same eye, which shows a student every step of their own renderer's computation
// there.
Counterexample pixel_counterexample(const GradingContext& context, const std::string& id,
                                    const std::string& scene_name, View view, const Vec3& eye,
                                    const Image& reference, const Image& student) {
    const Scene scene = load_scene(context.source / "scenes" / scene_name);
    const RenderPlace place = worst_render_place(scene_name, view, scene.width, scene.height,
                                                 reference, student, kStudentRaystep);
    return {place.input + ", " + moved_eye_text(eye), place.expected, place.got,
            context.reproduce + " --check " + id + " --case 0",
            place.trace + lookfrom_arguments(eye)};
}

// The probe's query for a render of the scene file at `scene_path`.
ProbeQuery render_query(const std::string& scene_path, View view, const CameraClip& clip,
                        const std::optional<Vec3>& eye) {
    probe::RenderQuestion question{
        scene_path, std::string(view_name(view)), kRenderCheckWidth, {}, {}, {}, eye, {}};
    if (!clip.name.empty()) {
        question.camera_t_min = clip.t_min;
        question.camera_t_max = clip.t_max;
    }
    return probe::query(probe::render_call, question);
}

std::string render_input(const std::string& scene, View view, const CameraClip& clip,
                         const std::optional<Vec3>& eye) {
    std::string input = scene + ", " + std::string(view_name(view)) + " view";
    if (!clip.name.empty()) {
        input +=
            ", camera rays over [" + full_text(clip.t_min) + ", " + full_text(clip.t_max) + "]";
    }
    if (eye) input += ", " + moved_eye_text(*eye);
    return input;
}

// Stage 4's renders go through the submission's SAH BVH, and a right image earns its points only
// from a BVH that does a structure's work, as the closest-hit checks do (measure_work, measured
// once per probe and shared with them): brute force behind a single leaf renders right too.
CheckMeasure with_bvh_work(const GradingContext& context, const BuiltProbe& probe,
                           const std::string& id, CheckMeasure measure) {
    const CheckMeasure work = measure_work(context, probe, {id, "bvh", "sah"});
    if (work.outcome == Outcome::passed) return measure;
    measure.outcome = Outcome::failed;
    measure.fraction = 0.0;
    measure.summary += "; but the BVH that rendered it: " + work.summary;
    return measure;
}

CheckMeasure measure_render(const GradingContext& context, const BuiltProbe& probe, int stage,
                            const std::string& id, const std::string& scene, View view,
                            const CameraClip& clip) {
    const fs::path path = context.source / "scenes" / scene;
    const Vec3 eye = moved_eye(load_scene(path).camera, context.eye_seed, id);
    const std::string input = render_input(scene, view, clip, eye);
    // The judge keeps the image; the diff comes once the run is over.
    std::optional<Image> student;
    ProbeCase render_case{
        input, render_query(path.string(), view, clip, eye),
        [&student](const ProbeAnswer& answer) {
            if (answer.kind != ProbeAnswer::Kind::result) return wrong("an image", "");
            student = probe::image_from(
                answer.value, static_cast<std::size_t>(kRenderCheckWidth) * kRenderCheckWidth * 4);
            return right();
        },
        render_command(scene, view, eye)};
    ProbeRunLimits limits = scene_reading_limits(context);
    CheckMeasure measure = run_cases(context, id, probe, {render_case}, limits);
    if (!student) return measure;

    const Image reference = reference_render(path, view, clip, eye);
    // The rule `raystep compare` gives students (app/compare/render_rule.h).
    const RenderVerdict verdict = judge_render(reference, *student);
    const fs::path folder = context.report_folder / "renders" / id;
    write_image(reference, folder / "reference.png");
    write_image(*student, folder / "student.png");
    write_image(render_heat_map(reference, *student), folder / "difference.png");
    measure.images = {"renders/" + id + "/reference.png", "renders/" + id + "/student.png",
                      "renders/" + id + "/difference.png"};
    measure.fraction = 1.0 - verdict.share_over;
    const auto metrics = render_metrics(verdict.diff);
    measure.metrics = {metrics.begin(), metrics.end()};
    measure.outcome = verdict.passed ? Outcome::passed : Outcome::failed;
    if (measure.outcome == Outcome::failed) {
        measure.counterexamples = {
            verdict.diff.same_size
                ? pixel_counterexample(context, id, scene, view, eye, reference, *student)
                : Counterexample{render_case.input,
                                 std::to_string(reference.width()) + " x " +
                                     std::to_string(reference.height()) + " pixels",
                                 std::to_string(student->width()) + " x " +
                                     std::to_string(student->height()) + " pixels",
                                 context.reproduce + " --check " + id + " --case 0",
                                 render_case.student_reproduce}};
    }
    measure.summary = render_summary(verdict);
    if (stage == 4 && measure.outcome == Outcome::passed)
        return with_bvh_work(context, probe, id, measure);
    return measure;
}

// One render check: the stage it grades (0: the pipeline), the scene under scenes/, the view, and
// the camera rays' clip.
struct RenderCheck {
    int stage = 0;
    std::string scene;
    View view = View::full;
    CameraClip clip;

    std::string id() const {
        const std::string stem =
            fs::path(scene).stem().string() + (clip.name.empty() ? "" : "-" + clip.name);
        return (stage == 0 ? std::string("pipeline") : "stage" + std::to_string(stage)) +
               ".render." + stem + "." + std::string(view_name(view));
    }

    /// The grader's check moves the eye; a release's, from the scene's own, does not.
    std::string name(bool eye_moved) const {
        std::string text = "the " + std::string(view_name(view)) + " view of scenes/" + scene;
        if (eye_moved) text += " from an eye moved for each grade";
        if (!clip.name.empty()) text += ", camera rays cut to [t_min, t_max]";
        if (stage == 0) text += ", every stage from the submission";
        return text;
    }
};

std::vector<RenderCheck> render_check_list() {
    return {
        {2, "stage2/perspective-wide.test", View::rays, {}},
        {2, "stage2/orthographic.test", View::rays, {}},
        {3, "stage3/spheres-on-plane.test", View::depth, {}},
        {3, "stage3/spheres-on-plane.test", View::normal, {}},
        {3, "stage3/triangle-fan.test", View::barycentric, {}},
        {4, "stage4/sphere-field.test", View::depth, {}},
        // Camera rays from 9 to 25 along the field: the near spheres cut open, seen from inside,
        // and the floor beyond 25 gone. A structure whose leaf test or walk forgets t_min or
        // t_max shows the near spheres whole or the far floor.
        {4, "stage4/sphere-field.test", View::depth, {9.0, 25.0, "clipped"}},
        {5, "stage5/ellipsoids.test", View::normal, {}},
        {5, "stage5/table.test", View::depth, {}},
        {6, "stage6/cornell-box.test", View::shaded, {}},
        {6, "stage6/shininess-row.test", View::shaded, {}},
        {6, "stage6/acne-scale-1e4.test", View::shaded, {}},
        {7, "stage7/mirror-spheres.test", View::full, {}},
        {7, "stage7/facing-mirrors-depth5.test", View::full, {}},
        {0, "stage6/cornell-box.test", View::full, {}},
        {0, "stage7/mirror-spheres.test", View::full, {}},
        {0, "stage5/table.test", View::full, {}},
        // Stage 9's scenes render one sample per pixel with no area lights, so each pixel is one
        // deterministic path and the rule of every other render holds.
        {9, "stage9/glass-sphere.test", View::full, {}},
        {9, "stage9/nested-media.test", View::full, {}},
        {9, "stage9/total-internal-reflection.test", View::full, {}},
        {0, "stage9/glass-sphere.test", View::full, {}},
        // Stage 11's: each kind of surface detail in a scene of its own, shaded by the
        // reference's stage 6 through the submission's lookups.
        {11, "stage11/smooth-bunny.test", View::shaded, {}},
        {11, "stage11/textured.test", View::shaded, {}},
        {11, "stage11/bumps.test", View::shaded, {}},
    };
}

}  // namespace

std::vector<CheckDefinition> render_checks() {
    std::vector<CheckDefinition> checks;
    for (const RenderCheck& check : render_check_list()) {
        checks.push_back({check.id(), check.stage, "render", check.name(true),
                          [check](const GradingContext& context, const BuiltProbe& probe) {
                              return measure_render(with_eye_seed(context), probe, check.stage,
                                                    check.id(), check.scene, check.view,
                                                    check.clip);
                          }});
    }
    return checks;
}

std::vector<PublicCheck> render_public_checks(const fs::path& source) {
    std::vector<PublicCheck> checks;
    for (const RenderCheck& check : render_check_list()) {
        const fs::path path = source / "scenes" / check.scene;
        const Scene scene = load_scene(path);
        ProbeQuery query = render_query("scenes/" + check.scene, check.view, check.clip, {});
        checks.push_back({check.id(),
                          check.stage,
                          "render",
                          check.name(false),
                          {{render_input(check.scene, check.view, check.clip, {}), std::move(query),
                            render_judge(reference_render(path, check.view, check.clip, {}),
                                         check.scene, check.view, scene.width, scene.height),
                            render_command(check.scene, check.view, {})}}});
    }
    return checks;
}

}  // namespace raystep::grade
