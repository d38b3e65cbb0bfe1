#include "grader/grade/release.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/common.hpp>

#include "app/compare/noisy_render_comparison.h"
#include "app/compare/reference_image.h"
#include "app/compare/reference_trace.h"
#include "app/compare/sampled_reference.h"
#include "base/image/image_io.h"
#include "base/scene/scene_files.h"
#include "base/scene/scene_loader.h"
#include "grader/grade/release_grading.h"
#include "renderer/pixel_record.h"
#include "renderer/tile_renderer.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

// The student's README, written as the release's README.md in place of the instructor's.
const fs::path kStudentReadme = "docs/student-README.md";

// GitHub Classroom's autograding workflow, kept out of the instructor's .github/ so that it grades
// students' pushes and never the instructor's; the release holds it where GitHub runs it.
const fs::path kClassroomWorkflow = "release/github/classroom.yml";
const fs::path kReleaseWorkflow = ".github/workflows/classroom.yml";

// What a student's repository leaves out, relative to the repository's root: the instructor's
// folders, guide, README and scripts, and the instructor's .github/ (its workflows build the
// grader: in a student's repository they would run, and fail, on every push; the release's own
// workflow is written there below). Of scripts/ only the students' own are kept, so that an
// instructor's script added later stays out without anyone listing it.
// Of grading/, a release holds what `raystep grade` runs the public checks with: each stage's
// calls, their JSON and its judges (files named *_calls, *_json, *_judges, the layer of app/ by
// scripts/check-layers.py), and the CMakeLists.txt that builds them. The checks, the oracles and
// the tests are the instructor's.
bool withheld_from_grading(const fs::path& relative, bool is_directory) {
    const std::vector<fs::path> parts(relative.begin(), relative.end());
    if (parts.size() == 2) return !is_directory && parts[1] != "CMakeLists.txt";
    if (parts.size() != 3 || is_directory) return true;
    const std::string extension = relative.extension().string();
    if (extension != ".h" && extension != ".cpp") return true;
    const std::string stem = relative.stem().string();
    for (const std::string suffix : {"_calls", "_json", "_judges"}) {
        if (stem.size() > suffix.size() &&
            stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0) {
            return false;
        }
    }
    return true;
}

bool withheld(const fs::path& relative, bool is_directory) {
    const std::string first = relative.begin()->string();
    if (first == "grading" && relative != "grading") {
        return withheld_from_grading(relative, is_directory);
    }
    if (first == "solutions" || first == "studies" || first == "grader" || first == ".git" ||
        first == ".ci" || first == ".github" || first == "build" || first == "out" ||
        first == "release") {
        return true;
    }
    if (first == "scripts" && relative != "scripts") {
        for (const char* students :
             {"scripts/setup.sh", "scripts/test.sh", "scripts/install-deps.sh"}) {
            if (relative == fs::path(students)) return false;
        }
        return true;
    }
    for (const char* instructors : {"README.md", "docs/instructor.md", "scenes/meshes"}) {
        if (relative == fs::path(instructors)) return true;
    }
    return relative == kStudentReadme;
}

std::size_t copy_tree(const fs::path& source, const fs::path& output) {
    std::size_t files = 0;
    for (auto it = fs::recursive_directory_iterator(source);
         it != fs::recursive_directory_iterator(); ++it) {
        const fs::path relative = fs::relative(it->path(), source);
        if (withheld(relative, it->is_directory())) {
            if (it->is_directory()) it.disable_recursion_pending();
            continue;
        }
        const fs::path target = output / relative;
        if (it->is_directory()) {
            fs::create_directories(target);
        } else if (it->is_regular_file()) {
            fs::copy_file(it->path(), target);
            ++files;
        }
    }
    return files;
}

// The image as an 8-bit file holds it: each channel clamped to [0, 1] (image_io.h).
Image clamped(Image image) {
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i)
            image.set(i, j, glm::clamp(image.at(i, j), Color(0.0), Color(1.0)));
    }
    return image;
}

// A sampled view's reference (sampled_reference.h): the mean of kSampledReferenceRenders renders
// at the seeds kSampledReferenceSeeds + k as the reference image, and their tile deviations
// beside it. Each render is clamped first, as the student's PNG is, so that a pixel brighter than
// white (a light seen directly) is averaged as the student's render holds it. `records` is filled
// while the first renders.
void write_sampled_reference(const Scene& scene, View view, const fs::path& image,
                             std::vector<PixelRecord>* records) {
    // One preparation (the BVH) serves every seed: the render scene reads the seed from `seeded`
    // as it renders.
    Scene seeded = scene;
    const RenderScene render_scene = prepare_render_scene(seeded);
    std::vector<Image> renders;
    for (int k = 0; k < kSampledReferenceRenders; ++k) {
        seeded.seed = kSampledReferenceSeeds + static_cast<std::uint64_t>(k);
        RenderOptions options;
        options.view = view;
        if (k == 0) options.records = records;
        renders.push_back(clamped(render_image(render_scene, options)));
    }
    write_image(mean_image(renders), image);
    write_image(tile_deviations(renders, kSampledTile), tile_spread_path(image));
}

}  // namespace

ReleaseSummary make_release(const fs::path& source, const fs::path& output) {
    if (fs::exists(output) && !fs::is_empty(output)) {
        throw std::runtime_error(output.string() +
                                 " is not empty: a release goes into a new folder");
    }
    fs::create_directories(output);
    ReleaseSummary summary;
    summary.files = copy_tree(source, output);
    fs::copy_file(source / kStudentReadme, output / "README.md");
    ++summary.files;
    fs::create_directories((output / kReleaseWorkflow).parent_path());
    fs::copy_file(source / kClassroomWorkflow, output / kReleaseWorkflow);
    ++summary.files;

    for (const auto& entry : fs::recursive_directory_iterator(source / "scenes")) {
        if (entry.path().extension() != ".test") continue;
        const fs::path relative = fs::relative(entry.path(), source / "scenes");
        try {
            const Scene scene = load_scene(entry.path());
            const RenderScene render_scene = prepare_render_scene(scene);
            // The reference's steps of every pixel, as far as its furthest view takes them,
            // recorded while that view renders: what `raystep trace --compare` holds a student's
            // pixel against.
            // Each a view: reference_views throws for a word that is not one.
            const std::vector<std::string> views = reference_views(entry.path());
            if (views.empty()) continue;
            std::string furthest = views.front();
            for (const std::string& name : views) {
                if (pipeline_reach(*parse_view(name)) > pipeline_reach(*parse_view(furthest)))
                    furthest = name;
            }
            std::vector<PixelRecord> records;
            for (const std::string& name : views) {
                const View view = *parse_view(name);
                const fs::path image = reference_image_path(output / "scenes" / relative, name);
                std::vector<PixelRecord>* view_records = name == furthest ? &records : nullptr;
                if (is_sampled_view(scene, view)) {
                    write_sampled_reference(scene, view, image, view_records);
                } else {
                    RenderOptions options;
                    options.view = view;
                    options.records = view_records;
                    write_image(render_image(render_scene, options), image);
                }
                ++summary.reference_images;
            }
            write_reference_trace(reference_trace_path(output / "scenes" / relative), scene.width,
                                  scene.height, *parse_view(furthest),
                                  scene.point_lights.size() + scene.directional_lights.size(),
                                  records, scene_digest(scene));
            ++summary.reference_traces;
        } catch (const std::exception& error) {
            summary.skipped.push_back(relative.string() + ": " + error.what());
        }
    }
    summary.public_checks = write_release_grading(
        source, source / "grader" / "rubric" / "rubric.json", output / "grading");
    return summary;
}

}  // namespace raystep::grade
