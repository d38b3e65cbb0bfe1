#include "report_example.h"

#include <algorithm>
#include <stdexcept>

#include <glm/common.hpp>

#include "base/image/image.h"
#include "base/image/image_io.h"

namespace raystep::testing {

using grade::CheckResult;
using grade::Counterexample;
using grade::Outcome;
using grade::Visibility;

const std::string kHostile =
    "</pre><script>alert(\"x\")</script><img src=x onerror='alert(1)'> ]]> &amp; & "
    "\x1b[31mred\x1b[0m\rpassed \x01\x02\x7f \xe2\x80\xae"
    "desrever \xff\xfe\xc3( \xed\xa0\x80"
    " end";

const std::string kHiddenSecret = "SECRET-hidden-family";

namespace {

CheckResult check(std::string id, int stage, std::string kind, std::string name, Outcome outcome,
                  double score, double max_score, std::string summary) {
    CheckResult result;
    result.id = std::move(id);
    result.stage = stage;
    result.kind = std::move(kind);
    result.name = std::move(name);
    result.outcome = outcome;
    result.score = score;
    result.max_score = max_score;
    result.summary = std::move(summary);
    return result;
}

// What the instructor runs to see the case again: raystep-grade, which no student has.
std::string instructor_command(const std::string& id, int case_index) {
    return "raystep-grade submission 'submissions/alice & bob.zip' --check " + id + " --case " +
           std::to_string(case_index) + " --instructor";
}

// The compiler output of a stage that does not compile: more lines than the console shows.
std::string compiler_output() {
    std::string text =
        "stages/5_transforms/transforms.cpp: In function 'glm::dmat4 "
        "raystep::rotate(double, const glm::dvec3&)':\n"
        "stages/5_transforms/transforms.cpp:41:12: error: 'cos_theta' was not declared in this "
        "scope; did you mean 'std::cos'?\n"
        "   41 |     return cos_theta * I + (1 - cos_theta) * outer(a, a) && <iostream>;\n"
        "      |            ^~~~~~~~~\n";
    for (int line = 50; line < 62; ++line) {
        text += "stages/5_transforms/transforms.cpp:" + std::to_string(line) +
                ":5: error: expected ';' before '}' token\n";
    }
    return text;
}

// A 48 x 32 image: a sky gradient, a magenta disc (the marker), and a grey floor. The student's
// disc is shifted right by `shift` pixels.
Image scene_image(int shift) {
    Image image(48, 32);
    for (int j = 0; j < 32; ++j) {
        for (int i = 0; i < 48; ++i) {
            const double dx = i - 20 - shift;
            const double dy = j - 14;
            if (dx * dx + dy * dy < 81.0) {
                image.set(i, j, {1.0, 0.0, 1.0});
            } else if (j > 24) {
                image.set(i, j, {0.45, 0.45, 0.45});
            } else {
                image.set(i, j, {0.35, 0.55 + 0.01 * j, 0.95});
            }
        }
    }
    return image;
}

// The difference of two images as a heat map: black where equal, red to yellow with the error.
Image heat_map(const Image& a, const Image& b) {
    Image map(a.width(), a.height());
    for (int j = 0; j < a.height(); ++j) {
        for (int i = 0; i < a.width(); ++i) {
            const Color d = glm::abs(a.at(i, j) - b.at(i, j));
            const double error = (d.r + d.g + d.b) / 3.0;
            map.set(
                i, j,
                {std::min(1.0, 3.0 * error), std::min(1.0, std::max(0.0, 3.0 * error - 1.0)), 0.0});
        }
    }
    return map;
}

}  // namespace

grade::GradeReport example_report() {
    grade::GradeReport report;
    report.submission = "submissions/alice & bob's <stage 7>.zip";
    report.student = "alice <b>& \"bob\"";
    report.times = {0.4, 12.25, 31.5, 0.2};

    report.checks.push_back(check("stage1.unit.dot", 1, "unit", "dot, cross and length by hand",
                                  Outcome::passed, 2, 2, "12 of 12 cases right"));
    report.checks.push_back(check("stage1.oracle.frames", 1, "oracle",
                                  "orthonormal frames of random and nearly parallel vectors",
                                  Outcome::passed, 3, 3, "1000 of 1000 cases right"));

    CheckResult stub =
        check("stage2.unit.perspective", 2, "unit", "perspective rays through pixel centres",
              Outcome::not_implemented, 0, 4,
              "stage 2: perspective_ray is not implemented yet, see docs/stage2.md");
    report.checks.push_back(stub);

    CheckResult edges = check("stage3.oracle.shared-edges", 3, "oracle",
                              "rays through shared edges of closed meshes", Outcome::failed, 1.5, 5,
                              "97 of 100 cases right; 3 false misses (leaks through an edge)");
    edges.counterexamples = {
        {"ray (0.25, 0.25, 5) + t (0, 0, -1) against the octahedron's edge (0,0,1)-(1,0,0)",
         "hit at t = 4.75 (either neighbour)", "miss by both neighbours",
         instructor_command("stage3.oracle.shared-edges", 17),
         "raystep check --stage 3 --family shared-edges --case 17"},
        {"ray (1e5, 1e5, 5) + t (0, 0, -1), a far copy of case 17", "hit at t = 5", kHostile,
         instructor_command("stage3.oracle.shared-edges", 42),
         "raystep check --stage 3 --family shared-edges --case 42"},
        // No command a student can run: their report shows none.
        {"ray (0.5, 0.5, 5) + t (0, 0, -1)", "hit at t = 4.5", "miss",
         instructor_command("stage3.oracle.shared-edges", 64), ""},
    };
    edges.metrics = {{"pass_rate", 0.97}, {"false_misses", 3}, {"max_t_error_ulps", 2}};
    report.checks.push_back(edges);

    CheckResult sphere = check("stage3.unit.sphere", 3, "unit", "ray-sphere by hand",
                               Outcome::crashed, 0, 2, "the probe died of SIGSEGV");
    sphere.details =
        "signal 11 (SIGSEGV) while answering intersect_sphere; its output:\n" + kHostile;
    report.checks.push_back(sphere);

    CheckResult hidden = check("stage3.oracle.grazing-" + kHiddenSecret, 3, "oracle",
                               "grazing rays, " + kHiddenSecret, Outcome::failed, 0, 4,
                               "0 of 50 right on " + kHiddenSecret);
    hidden.visibility = Visibility::hidden;
    hidden.counterexamples = {{"input " + kHiddenSecret, "hit", "miss",
                               instructor_command("stage3.oracle.grazing-" + kHiddenSecret, 3),
                               "raystep check --stage 3 --family " + kHiddenSecret}};
    hidden.details = "details " + kHiddenSecret;
    report.checks.push_back(hidden);

    CheckResult bvh = check("stage4.speed.bvh-sah", 4, "speed", "BVH (SAH) against brute force",
                            Outcome::timed_out, 0, 3, "ran past the 20 s wall-clock limit");
    bvh.details = "killed after 20.0 s on the 16 bunnies workload";
    report.checks.push_back(bvh);

    CheckResult transforms =
        check("stage5.unit.rotate", 5, "unit", "rotation about an axis", Outcome::did_not_compile,
              0, 4, "stages/5_transforms/transforms.cpp did not compile");
    transforms.details = compiler_output();
    report.checks.push_back(transforms);

    CheckResult shadows =
        check("stage6.render.shadows", 6, "render", "shadow rays, Cornell-like room",
              Outcome::passed, 3, 3, "PSNR 52.3 dB; 0.01% of pixels over 0.05");
    shadows.visibility = Visibility::after_due_date;
    shadows.metrics = {{"psnr", 52.3}, {"rmse", 0.0024}};
    shadows.images = {"render/shadows-reference.png", "render/shadows-student.png", ""};
    shadows.counterexamples = {
        {"pixel (7, 9) of scenes/stage6/SHADOWS-after-due-date.test " + kHostile, "(0.1, 0.1, 0.1)",
         "(0.5, 0.5, 0.5)", instructor_command("stage6.render.shadows", 0),
         "raystep trace scenes/stage6/SHADOWS-after-due-date.test 7 9"}};
    report.checks.push_back(shadows);

    CheckResult mirrors =
        check("stage7.render.mirrors", 7, "render", "mirror spheres at maxdepth 5", Outcome::failed,
              2, 5, "PSNR 21.4 dB; 6.1% of pixels over 0.05 (reflections offset)");
    mirrors.metrics = {{"mae", 0.0123},
                       {"rmse", 0.0851},
                       {"psnr", 21.4},
                       {"over_threshold", 0.061},
                       {"flip", 0.114}};
    mirrors.images = {"render/mirrors reference.png", "render/mirrors student #1.png",
                      "render/mirrors-difference.png"};
    mirrors.counterexamples = {{"pixel (31, 12) of scenes/stage7/mirrors.test", "(0.82, 0.1, 0.77)",
                                "(0.41, 0.5, 0.93)", instructor_command("stage7.render.mirrors", 0),
                                "raystep trace scenes/stage7/mirrors.test 31 12 --compare"}};
    report.checks.push_back(mirrors);

    CheckResult published = check("stage7.unit.depth", 7, "unit", "recursion stops at maxdepth",
                                  Outcome::passed, 1, 1, "4 of 4 cases right");
    published.visibility = Visibility::after_published;
    published.counterexamples = {{"maxdepth PUBLISHED-depth-input " + kHostile, "3 bounces",
                                  "3 bounces", instructor_command("stage7.unit.depth", 2),
                                  "raystep check --stage 7 --case PUBLISHED-depth-input"}};
    report.checks.push_back(published);

    CheckResult pipeline = check("pipeline.render.cse167-scene7", 0, "render",
                                 "the whole pipeline on CSE167's scene 7", Outcome::passed, 4, 4,
                                 "PSNR 48.0 dB; no pixel over 0.05");
    pipeline.metrics = {{"psnr", 48.0}, {"rmse", 0.004}};
    pipeline.images = {"render/mirrors reference.png", "render/mirrors reference.png",
                       "render/mirrors-difference-none.png"};
    report.checks.push_back(pipeline);

    // Times a quarter second apart, so that each sum of them is its own.
    for (std::size_t k = 0; k < report.checks.size(); ++k)
        report.checks[k].seconds = 0.25 * static_cast<double>(k + 1);
    return report;
}

const CheckResult& find_check(const grade::GradeReport& report, const std::string& id) {
    for (const CheckResult& check : report.checks) {
        if (check.id == id) return check;
    }
    throw std::out_of_range("the example report has no check " + id);
}

void write_example_images(const std::filesystem::path& folder) {
    const Image reference = scene_image(0);
    const Image student = scene_image(3);
    write_image(reference, folder / "render/mirrors reference.png");
    write_image(student, folder / "render/mirrors student #1.png");
    write_image(heat_map(reference, student), folder / "render/mirrors-difference.png");
    write_image(heat_map(reference, reference), folder / "render/mirrors-difference-none.png");
    write_image(reference, folder / "render/shadows-reference.png");
    // render/shadows-student.png is left out on purpose: the report shows it as missing.
}

}  // namespace raystep::testing
