// The `raystep` command as a student runs it: the exit code and the message of each command, on
// good input and bad. Each test runs the program in a scratch folder of its own, and makes there
// whatever files it reads (a reference render, trace data, a small repository to submit).

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "base/testing/catch.h"
#include "base/testing/command_run.h"
#include "base/testing/scratch_folder.h"

using raystep::testing::check_run;
using raystep::testing::CommandRun;
using raystep::testing::PrintsInOrder;
using raystep::testing::ScratchFolder;

namespace fs = std::filesystem;

namespace {

const fs::path kData = RAYSTEP_TEST_DATA;
const fs::path kSource = RAYSTEP_SOURCE_DIR;
const fs::path kQuad = kData / "good/quad.test";

// `program` (the configured stages' raystep, or raystep-reference) with `arguments`, in `folder`.
CommandRun run_in(const fs::path& folder, const std::string& program,
                  std::vector<std::string> arguments) {
    arguments.insert(arguments.begin(), program);
    return raystep::testing::run_command(arguments, folder);
}

CommandRun raystep_in(const fs::path& folder, std::vector<std::string> arguments) {
    return run_in(folder, RAYSTEP_PROGRAM, std::move(arguments));
}

CommandRun reference_in(const fs::path& folder, std::vector<std::string> arguments) {
    return run_in(folder, RAYSTEP_REFERENCE_PROGRAM, std::move(arguments));
}

// `raystep ARGUMENTS` in a scratch folder of its own, judged by check_run.
void check_raystep(std::vector<std::string> arguments, int exit_code,
                   std::vector<std::string> patterns) {
    arguments.insert(arguments.begin(), RAYSTEP_PROGRAM);
    raystep::testing::check_command(arguments, exit_code, std::move(patterns));
}

void write_file(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

std::string regex_escaped(const std::string& text) {
    static const std::string special = R"(\^$.|?*+()[]{})";
    std::string escaped;
    for (const char c : text) {
        if (special.find(c) != std::string::npos) escaped += '\\';
        escaped += c;
    }
    return escaped;
}

}  // namespace

// Every bad scene of base/tests/data/bad_scenes/ says on its first line where its error is
// ("# expect: LINE: ..."; line 0 for the file as a whole).
TEST_CASE("raystep command: info on every bad scene reports its file:line and exits 1", "[cli]") {
    const ScratchFolder folder("bad-scenes");
    int scenes = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(kData / "bad_scenes")) {
        if (entry.path().extension() != ".test") continue;
        ++scenes;
        INFO(entry.path().filename().string());
        std::string first;
        std::getline(std::ifstream(entry.path()), first);
        const std::string prefix = "# expect: ";
        REQUIRE(first.rfind(prefix, 0) == 0);
        const std::string line =
            first.substr(prefix.size(), first.find(':', prefix.size()) - prefix.size());
        const std::string where = "bad_scenes/" + entry.path().filename().string() + ":" +
                                  (line == "0" ? "" : line + ":") + " ";
        const CommandRun run = raystep_in(folder.path(), {"info", entry.path().string()});
        INFO("it printed:\n" << run.output());
        CHECK(run.exit_code == 1);
        CHECK_THAT(run.output(), PrintsInOrder({regex_escaped(where)}));
    }
    CHECK(scenes > 50);
}

TEST_CASE("raystep command: no subcommand prints usage and exits 2", "[cli]") {
    check_raystep({}, 2, {"render"});
}

TEST_CASE("raystep command: an unknown command exits 2 and lists the commands of this build",
          "[cli]") {
    check_raystep(
        {"teapot"}, 2,
        {"no command 'teapot' in this build; its commands are: render, info, trace, check, "});
}

TEST_CASE("raystep command: a missing scene file exits 2", "[cli]") {
    check_raystep({"render", (kData / "no-such-scene.test").string()}, 2, {"File does not exist"});
}

TEST_CASE("raystep command: an unknown view exits 2 and lists the views", "[cli]") {
    check_raystep({"render", kQuad.string(), "--view", "colours"}, 2, {"rays"});
}

TEST_CASE("raystep command: a zero thread count exits 2", "[cli]") {
    check_raystep({"render", kQuad.string(), "--threads", "0"}, 2, {"threads"});
}

TEST_CASE("raystep command: trace of a pixel outside the image exits 1", "[cli]") {
    check_raystep({"trace", kQuad.string(), "64", "0"}, 1,
                  {R"(pixel \(64, 0\) is outside the 64 x 48 image)"});
}

TEST_CASE("raystep command: render writes the image and says where", "[cli]") {
    const ScratchFolder folder("render");
    const fs::path image = folder.path() / "n.png";
    const CommandRun run = raystep_in(
        folder.path(), {"render", kQuad.string(), "--view", "normal", "-o", image.string()});
    check_run(run, 0, {R"(wrote .*/n.png \(64 x 48, view normal)"});
    CHECK(fs::file_size(image) > 0);
}

// Without -o, under out/ in the working folder, named for the scene's folder, the scene and the
// view.
TEST_CASE("raystep command: render without -o writes out/FOLDER/SCENE.VIEW.png", "[cli]") {
    const ScratchFolder folder("render");
    const CommandRun run = raystep_in(folder.path(), {"render", kQuad.string(), "--view", "depth"});
    check_run(run, 0, {R"(wrote out/good/quad.depth.png \(64 x 48, view depth)"});
    CHECK(fs::exists(folder.path() / "out/good/quad.depth.png"));
}

TEST_CASE("raystep command: render of the full image shades it", "[cli]") {
    check_raystep({"render", kQuad.string(), "-o", "quad-full.png"}, 0,
                  {R"(wrote quad-full.png \(64 x 48, view full)"});
}

TEST_CASE("raystep command: render with a ray offset rule and its epsilon", "[cli]") {
    check_raystep({"render", kQuad.string(), "--ray-offset", "along-normal", "--epsilon", "1e-4",
                   "-o", "quad-offset.png"},
                  0, {"wrote quad-offset.png"});
}

TEST_CASE("raystep command: render --spp overrides the scene's samples per pixel and says so",
          "[cli]") {
    check_raystep({"render", kQuad.string(), "--spp", "4", "--seed", "3", "-o", "quad-spp.png"}, 0,
                  {R"(wrote quad-spp.png \(64 x 48, view full, 4 spp)"});
}

TEST_CASE("raystep command: render --spp that is not a square cannot be jittered and exits 1",
          "[cli]") {
    check_raystep({"render", kQuad.string(), "--spp", "5", "-o", "quad-spp5.png"}, 1,
                  {"5 samples per pixel cannot be placed jittered"});
}

TEST_CASE("raystep command: render --seed -1 is refused as the scene's seed -1 is, and exits 2",
          "[cli]") {
    check_raystep({"render", kQuad.string(), "--seed", "-1", "-o", "quad-seed.png"}, 2,
                  {R"(the seed is a whole number from 0 to 2\^64 - 1)"});
}

// A CSE168 setting that raystep reads but does not render is said, as file:line: warning.
TEST_CASE("raystep command: render says what the scene asks for that it does not render", "[cli]") {
    const ScratchFolder folder("render");
    write_file(folder.path() / "pathtracer-note.test",
               "size 4 4\ncamera 0 0 5 0 0 0 0 1 0 45\nintegrator pathtracer\nsphere 0 0 0 1\n");
    const CommandRun run =
        raystep_in(folder.path(), {"render", "pathtracer-note.test", "-o", "note.png"});
    check_run(run, 0, {"pathtracer-note.test:3: warning: 'integrator pathtracer'"});
}

// A light on a surface that a ray sees has no direction to shade by: the scene's error, on the
// light's line.
TEST_CASE("raystep command: a point light on a seen surface is an error on the light's line",
          "[cli]") {
    const ScratchFolder folder("render");
    write_file(folder.path() / "light-on-floor.test",
               "size 9 9\ncamera 0 3 0 0 0 0 0 0 -1 45\northo -2.25 2.25 -2.25 2.25\n"
               "diffuse 0.5 0.5 0.5\nplane 0 0 0 0 1 0\npoint 0.5 0 -1 1 1 1\n");
    const CommandRun run =
        raystep_in(folder.path(), {"render", "light-on-floor.test", "-o", "floor.png"});
    check_run(run, 1,
              {R"(light-on-floor.test:6: the light is at \(0.5, 0, -1\), a point of a )"
               "surface that a ray sees"});
}

TEST_CASE("raystep command: trace --compare refuses a moved eye and exits 2", "[cli]") {
    check_raystep({"trace", kQuad.string(), "1", "1", "--compare", "--lookfrom", "1", "0", "4"}, 2,
                  {"leave out --ray-offset and --lookfrom"});
}

TEST_CASE("raystep command: render from an eye at the scene's look-at point exits 1", "[cli]") {
    check_raystep({"render", kQuad.string(), "--lookfrom", "0", "0", "0", "-o", "quad-nowhere.png"},
                  1, {"--lookfrom is the scene's look-at point"});
}

TEST_CASE("raystep command: trace --compare refuses sampling overrides and exits 1", "[cli]") {
    check_raystep({"trace", kQuad.string(), "1", "1", "--compare", "--spp", "4"}, 1,
                  {"leave out --spp"});
}

TEST_CASE("raystep command: a ray offset rule that measures in epsilon without one exits 2",
          "[cli]") {
    check_raystep({"render", kQuad.string(), "--ray-offset", "along-ray"}, 2,
                  {"along-ray needs --epsilon"});
}

TEST_CASE("raystep command: an epsilon of 0 exits 2: the offset distance must be above 0",
          "[cli]") {
    check_raystep({"render", kQuad.string(), "--ray-offset", "along-ray", "--epsilon", "0"}, 2,
                  {"--epsilon: the offset distance must be a number above 0, not '0'"});
}

TEST_CASE("raystep command: an epsilon for error-bound exits 2", "[cli]") {
    check_raystep({"render", kQuad.string(), "--ray-offset", "error-bound", "--epsilon", "1"}, 2,
                  {"error-bound takes no --epsilon"});
}

TEST_CASE("raystep command: an epsilon without a rule exits 2", "[cli]") {
    check_raystep({"trace", kQuad.string(), "1", "1", "--epsilon", "1e-3"}, 2,
                  {"--epsilon: needs --ray-offset"});
}

TEST_CASE("raystep command: an unknown ray offset rule exits 2 and lists the rules", "[cli]") {
    check_raystep({"render", kQuad.string(), "--ray-offset", "nudge", "--epsilon", "1"}, 2,
                  {"error-bound"});
}

TEST_CASE("raystep command: info lists features and stages", "[cli]") {
    check_raystep({"info", kQuad.string()}, 0,
                  {"dialect     CSE167, the ray tracer's",
                   "primitives  2 primitives: 0 spheres, 2 triangles, 0 planes",
                   "stages      full image 1 2 3 6"});
}

TEST_CASE(
    "raystep command: info lists area lights, sampling and the CSE168 settings it does "
    "not use",
    "[cli]") {
    check_raystep({"info", (kData / "good/cornell_quadlight.test").string()}, 0,
                  {"dialect     CSE168, the path tracer's", R"(area light \(quadLight\))",
                   "sampling    4 samples per pixel, jittered; 16 samples per area light, "
                   "stratified"});
}

TEST_CASE("raystep command: info warns of a CSE168 setting raystep does not use, naming its line",
          "[cli]") {
    check_raystep({"info", (kData / "good/cse168_path_tracer_settings.test").string()}, 0,
                  {"cse168_path_tracer_settings.test:5: warning: 'russianroulette' has no effect "
                   "outside 'integrator pathtracer'"});
}

TEST_CASE(
    "raystep command: a CSE168 homework scene renders as written, warning where the "
    "dialects differ",
    "[cli]") {
    const fs::path scene = kData / "good/cse168_homework_scene.test";
    check_raystep({"info", scene.string()}, 0,
                  {"dialect     CSE168", R"(maxdepth -1 \(no limit\))",
                   "paths \\(integrator pathtracer\\) of any length, ended by Russian roulette, "
                   "directions drawn cosine-weighted, next event estimation on",
                   "cse168_homework_scene.test:16: warning: more vertices than 'maxverts 3'",
                   "cse168_homework_scene.test:19: warning: in the CSE168 dialect 'specular'",
                   "cse168_homework_scene.test:21: warning: no 'ambient' is written above",
                   "cse168_homework_scene.test:26: warning: in the CSE168 dialect a quadLight"});
    const ScratchFolder folder("cse168");
    check_raystep({"render", scene.string(), "-o", (folder.path() / "homework.png").string()}, 0,
                  {"wrote ", "cse168_homework_scene.test:5: warning: 'integrator pathtracer'"});
}

TEST_CASE("raystep command: trace prints the camera ray and the closest hit", "[cli]") {
    check_raystep({"trace", kQuad.string(), "32", "24", "--view", "depth"}, 0,
                  {R"(camera ray: origin \(0, 0, 4\))", "closest_hit: triangle"});
}

// Glibc's loader trace (LD_DEBUG=libs) tells whether a run loaded OpenImageIO: the commands that
// read or write no image start without it, which the image library module
// (base/image/image_library_loader.h) brings in on the first image.
#if defined(__linux__)
namespace {

// How many libraries named OpenImageIO `raystep ARGUMENTS` initialised; the run must exit 0.
int openimageio_libraries_loaded(const fs::path& folder,
                                 const std::vector<std::string>& arguments) {
    std::vector<std::string> words{RAYSTEP_PROGRAM};
    words.insert(words.end(), arguments.begin(), arguments.end());
    const CommandRun run = raystep::testing::run_command(words, folder, {"LD_DEBUG=libs"});
    std::string shown = "raystep";
    for (const std::string& argument : arguments)
        shown += " " + argument;
    INFO(shown << " printed:\n" << run.out);
    CHECK(run.exit_code == 0);
    int loaded = 0;
    std::istringstream trace(run.err);
    for (std::string line; std::getline(trace, line);) {
        if (line.find("calling init:") != std::string::npos &&
            line.find("OpenImageIO") != std::string::npos)
            ++loaded;
    }
    return loaded;
}

}  // namespace

TEST_CASE("raystep command: --help, info, trace and check start without loading OpenImageIO",
          "[cli]") {
    const ScratchFolder folder("loaded");
    const std::string cases = (kSource / "stages/3_intersect/cases/axis-parallel.cases").string();
    CHECK(openimageio_libraries_loaded(folder.path(), {"--help"}) == 0);
    CHECK(openimageio_libraries_loaded(folder.path(), {"info", kQuad.string()}) == 0);
    CHECK(openimageio_libraries_loaded(folder.path(), {"trace", kQuad.string(), "32", "24"}) == 0);
    CHECK(openimageio_libraries_loaded(folder.path(), {"check", "--stage", "3", cases}) == 0);
}

TEST_CASE("raystep command: render loads OpenImageIO on first use and writes a PNG", "[cli]") {
    const ScratchFolder folder("loaded");
    CHECK(openimageio_libraries_loaded(folder.path(), {"render", kQuad.string(), "-o", "q.png"}) >
          0);
    CHECK(raystep::testing::file_text(folder.path() / "q.png").substr(0, 8) == "\x89PNG\r\n\x1a\n");
}
#endif

// `raystep check` on the hand-computed case files, run by the reference build: every method passes
// the right file, and a deliberately wrong expectation comes back as a counterexample.
TEST_CASE("raystep command: check passes every reference method on the hand-computed cases",
          "[cli]") {
    const ScratchFolder folder("check");
    const CommandRun run = reference_in(
        folder.path(), {"check", "--stage", "3", (kData / "cases/axis-aligned.cases").string()});
    check_run(run, 0,
              {"closest_hit +axis-aligned +[0-9]+ +100.0%", "closest_hit +spheres +[0-9]+ +100.0%",
               " checks passed"});
}

TEST_CASE(
    "raystep command: check reports a wrong expectation as a counterexample with its rerun "
    "command",
    "[cli]") {
    const ScratchFolder folder("check");
    const CommandRun run = reference_in(
        folder.path(),
        {"check", "--stage", "3", (kData / "cases/wrong-expectation-fails.cases").string()});
    check_run(run, 1,
              {R"(case 0: false miss: primitive 0 \(sphere\): expected a hit at )"
               R"(t = 4, got a miss)",
               "rerun: raystep check --stage 3 ",
               "wrong-expectation-fails.cases --family deliberately-wrong --method "
               "intersect_sphere --case 0"});
}

TEST_CASE("raystep command: check --case shows each expectation beside each answer", "[cli]") {
    const ScratchFolder folder("check");
    const CommandRun run = reference_in(
        folder.path(), {"check", "--stage", "3", (kData / "cases/axis-aligned.cases").string(),
                        "--family", "axis-aligned", "--case", "0"});
    check_run(run, 0,
              {R"(primitive 3 \(triangle\): expected hit at t = 5 )",
               R"(intersect_triangle_cramer +hit at t = 5, normal \(0, 0, 1\), )"
               R"(barycentrics \(0.25, 0.5\))",
               R"(closest_hit +primitive 3 \(triangle\))"});
}

TEST_CASE("raystep command: check of a stage without case checks exits 2", "[cli]") {
    check_raystep({"check", "--stage", "4", (kData / "cases/axis-aligned.cases").string()}, 2,
                  {"only stage 3 has case checks"});
}

TEST_CASE("raystep command: check with an unknown family exits 1 and lists the families", "[cli]") {
    check_raystep(
        {"check", "--stage", "3", (kData / "cases/axis-aligned.cases").string(), "--family",
         "planes"},
        1, {"no family 'planes' in the case files; the families are: axis-aligned, spheres"});
}

TEST_CASE("raystep command: check with an unknown method exits 2 and lists the methods", "[cli]") {
    check_raystep({"check", "--stage", "3", (kData / "cases/axis-aligned.cases").string(),
                   "--method", "intersect_cone"},
                  2, {"intersect_triangle_cramer"});
}

TEST_CASE("raystep command: check of one family name in two files names both and exits 1",
          "[cli]") {
    const std::string cases = (kData / "cases/axis-aligned.cases").string();
    check_raystep({"check", "--stage", "3", cases, cases}, 1,
                  {"axis-aligned.cases: family 'axis-aligned' is in ", "axis-aligned.cases too"});
}

TEST_CASE("raystep command: check of a cut-off case file reports file:line and exits 1", "[cli]") {
    check_raystep({"check", "--stage", "3", (kData / "cases/bad/missing-end.cases").string()}, 1,
                  {"missing-end.cases:3: case 0 has no 'end'"});
}

// `raystep demo`: the list, a bad name, one demo written where -o says, and --size's limits (the
// sizes it draws at are measured by app/demo/tests/demo_size_test.py).
TEST_CASE("raystep command: demo without a name lists every demo", "[cli]") {
    check_raystep({"demo"}, 0,
                  {"ray-directions", "barycentrics", "watertight", "bvh-cost", "grid-cost",
                   "normal-transform", "shadow-acne"});
}

TEST_CASE("raystep command: demo --list lists every demo with what it shows", "[cli]") {
    check_raystep({"demo", "--list"}, 0, {"ray-directions +stage 2: ", "shadow-acne +stage 6: "});
}

TEST_CASE("raystep command: demo with an unknown name exits 2 and lists the demos", "[cli]") {
    check_raystep({"demo", "teapot"}, 2, {"teapot not in ", "ray-directions", "shadow-acne"});
}

TEST_CASE("raystep command: demo writes its image and says where and how long it took", "[cli]") {
    check_raystep({"demo", "ray-directions", "-o", "demo-rays.png"}, 0,
                  {R"(wrote demo-rays.png \(640 x 480, demo ray-directions, [0-9.]+ s\))"});
}

TEST_CASE(
    "raystep command: demo --size without an x between the numbers exits 2 saying how to "
    "write one",
    "[cli]") {
    check_raystep({"demo", "ray-directions", "--size", "1920"}, 2,
                  {"--size: '1920' has no 'x' between width and height: write WIDTHxHEIGHT in "
                   "pixels, such as 1920x1080"});
}

TEST_CASE("raystep command: demo --size of numbers that are not whole exits 2", "[cli]") {
    check_raystep({"demo", "ray-directions", "--size", "1920.5x1080"}, 2,
                  {"--size: '1920.5x1080' is not two whole numbers with an 'x' between"});
}

TEST_CASE("raystep command: demo --size below 320x240 exits 2 naming the smallest size", "[cli]") {
    check_raystep({"demo", "ray-directions", "--size", "160x120"}, 2,
                  {"--size: '160x120' is too small: a demo is at least 320 x 240"});
}

TEST_CASE("raystep command: demo --size above 3840x2160 exits 2 naming the largest size", "[cli]") {
    check_raystep({"demo", "ray-directions", "--size", "7680x4320"}, 2,
                  {"--size: '7680x4320' is too large: a demo is at most 3840 x 2160"});
}

// `raystep compare`: a render against a reference folder laid out as a student release has it
// (reference/<scene>.<view>.png beside the scene).
namespace {

// A scratch folder holding quad.test and what a test of compare asks for: the reference's normal
// view in reference/, and this build's renders beside the scene.
class CompareFolder {
  public:
    CompareFolder() : folder_("compare") { fs::copy_file(kQuad, path() / "quad.test"); }

    const fs::path& path() const { return folder_.path(); }

    void add_reference_normal() const {
        REQUIRE(reference_in(path(), {"render", "quad.test", "--view", "normal", "-o",
                                      "reference/quad.normal.png"})
                    .exit_code == 0);
    }
    void add_render(const std::string& view) const {
        REQUIRE(raystep_in(path(),
                           {"render", "quad.test", "--view", view, "-o", "quad." + view + ".png"})
                    .exit_code == 0);
    }

    CommandRun compare(std::vector<std::string> arguments) const {
        arguments.insert(arguments.begin(), "compare");
        return raystep_in(path(), std::move(arguments));
    }

  private:
    ScratchFolder folder_;
};

}  // namespace

TEST_CASE(
    "raystep command: compare of a render with its shipped reference passes and writes the "
    "heat map",
    "[cli]") {
    const CompareFolder folder;
    folder.add_reference_normal();
    folder.add_render("normal");
    const CommandRun run = folder.compare({"quad.normal.png", "-o", "quad-heat.png"});
    check_run(run, 0,
              {"reference +", "reference/quad.normal.png", "pixels over threshold +0", "heat map +",
               "quad-heat.png", R"(pass: 0 of 3072 pixels differ by more than 0.02 \(0.00%\))"});
    CHECK(fs::exists(folder.path() / "quad-heat.png"));
}

TEST_CASE("raystep command: compare of a wrong render fails with the grader's numbers", "[cli]") {
    const CompareFolder folder;
    folder.add_reference_normal();
    folder.add_render("depth");
    const CommandRun run = folder.compare({"quad.depth.png", "reference/quad.normal.png"});
    check_run(run, 1,
              {"pixels over threshold +784",
               R"(fail: 784 of 3072 pixels differ by more than 0.02 \(25.52%\). )"
               R"(RMSE 0.1979. the grader passes at most 0.50%)"});
}

TEST_CASE("raystep command: compare of images of different sizes fails and names both sizes",
          "[cli]") {
    const CompareFolder folder;
    folder.add_render("normal");
    const CommandRun run = folder.compare(
        {"quad.normal.png", (kSource / "docs/images/demos/ray-directions.png").string()});
    check_run(run, 1,
              {"fail: the image has the wrong size",
               "quad.normal.png is 64 x 48 pixels but the reference ",
               "ray-directions.png is 640 x 480"});
}

TEST_CASE(
    "raystep command: compare without a shipped reference exits 2 and lists the scene's "
    "references",
    "[cli]") {
    const CompareFolder folder;
    folder.add_reference_normal();
    folder.add_render("depth");
    const CommandRun run = folder.compare({"quad.depth.png"});
    check_run(run, 2,
              {"quad.depth.png: no reference image quad.depth.png in ",
               "the references of quad are: ", "reference/quad.normal.png"});
}

TEST_CASE(
    "raystep command: compare --scene without a reference for the view exits 2 before "
    "rendering",
    "[cli]") {
    const CompareFolder folder;
    folder.add_reference_normal();
    const CommandRun run = folder.compare({"--scene", "quad.test", "--view", "barycentric"});
    check_run(run, 2, {"quad.barycentric.png: no reference image quad.barycentric.png"});
    CHECK_FALSE(fs::exists(folder.path() / "out"));
}

TEST_CASE("raystep command: compare --scene of a scene with several reference views asks for one",
          "[cli]") {
    check_raystep(
        {"compare", "--scene", (kSource / "scenes/stage2/perspective-wide.test").string()}, 2,
        {"perspective-wide.test: the reference has the views rays, depth: pick one with "
         "--view"});
}

TEST_CASE("raystep command: compare with an unknown view exits 2 and lists the views", "[cli]") {
    const CompareFolder folder;
    folder.add_reference_normal();
    const CommandRun run = folder.compare({"--scene", "quad.test", "--view", "colours"});
    check_run(run, 2, {"colours not in ", "rays", "barycentric"});
}

TEST_CASE("raystep command: compare of a file that is not an image exits 2 naming it", "[cli]") {
    const CompareFolder folder;
    folder.add_reference_normal();
    const CommandRun run = folder.compare({"quad.test", "reference/quad.normal.png"});
    check_run(run, 2, {"quad.test: cannot read image"});
}

TEST_CASE("raystep command: compare of a missing image exits 2 naming it", "[cli]") {
    check_raystep({"compare", "no-such-render.png"}, 2, {"no-such-render.png: no such file"});
}

// The render goes under out/, named for the scene's folder, as render writes it without -o.
TEST_CASE(
    "raystep command: compare --scene renders with this build's stages and compares in one "
    "go",
    "[cli]") {
    const CompareFolder folder;
    fs::create_directories(folder.path() / "scene");
    fs::copy_file(kQuad, folder.path() / "scene/quad.test");
    REQUIRE(reference_in(folder.path(), {"render", "scene/quad.test", "--view", "normal", "-o",
                                         "scene/reference/quad.normal.png"})
                .exit_code == 0);
    const CommandRun run = folder.compare({"--scene", "scene/quad.test", "--view", "normal"});
    check_run(run, 0,
              {R"(wrote out/scene/quad.normal.png \(64 x 48, view normal)", "reference +",
               "scene/reference/quad.normal.png", "pass: 0 of 3072 pixels"});
}

// `raystep submit`, run where a student runs it: inside a repository, written here (whole, or
// with a manifest that lists a file it lacks), or in a stage folder of this source tree, whose
// stubs it must warn about. Python's zipfile reads back the zip it writes (each entry's CRC
// checked); the grader's own unpacker reads one in grader/grade/tests/submitted_zip_test.cpp.
namespace {

// A repository of stage 1 alone whose manifest lists `files`, each but norms.cpp written.
fs::path write_repository(const fs::path& root, const std::string& files) {
    write_file(root / "CMakePresets.json", "{}\n");
    write_file(root / "stages/1_vectors/manifest.txt", "# Stage 1\n" + files);
    write_file(root / "stages/1_vectors/vectors.cpp", "double dot() { return 0.0; }\n");
    return root / "stages/1_vectors";
}

// The stage folder of a whole repository after `raystep submit` ran there once.
fs::path submitted_repository(const fs::path& root) {
    const fs::path stage = write_repository(root, "vectors.cpp\n");
    const CommandRun run = raystep_in(stage, {"submit"});
    INFO(run.output());
    REQUIRE(run.exit_code == 0);
    return stage;
}

CommandRun python_zipfile(const fs::path& folder, const std::string& option) {
    return raystep::testing::run_command(
        {RAYSTEP_PYTHON, "-m", "zipfile", option, "submission.zip"}, folder);
}

}  // namespace

TEST_CASE("raystep command: submit writes submission.zip in the current folder and says where",
          "[cli]") {
    const ScratchFolder folder("submit");
    const fs::path stage = write_repository(folder.path(), "vectors.cpp\n");
    const CommandRun run = raystep_in(stage, {"submit"});
    check_run(run, 0,
              {"stages/1_vectors/vectors.cpp +29 bytes",
               R"(wrote .*stages/1_vectors/submission.zip \(1 file, )"});
    CHECK(fs::exists(stage / "submission.zip"));
}

TEST_CASE("raystep command: submit refuses to replace its zip without --force", "[cli]") {
    const ScratchFolder folder("submit");
    const CommandRun run = raystep_in(submitted_repository(folder.path()), {"submit"});
    check_run(run, 1, {"submission.zip already exists: --force replaces it"});
}

TEST_CASE("raystep command: submit's zip holds the manifest's file", "[cli]") {
    const ScratchFolder folder("submit");
    const CommandRun run = python_zipfile(submitted_repository(folder.path()), "-l");
    check_run(run, 0,
              {"File Name +Modified +Size\n"
               "stages/1_vectors/vectors.cpp +1980-01-01 00:00:00 +29\n$"});
}

TEST_CASE("raystep command: submit's zip has every entry's CRC right", "[cli]") {
    const ScratchFolder folder("submit");
    const CommandRun run = python_zipfile(submitted_repository(folder.path()), "-t");
    check_run(run, 0, {"Done testing"});
}

TEST_CASE(
    "raystep command: submit from a stage folder lists every manifest file and warns of "
    "stubs",
    "[cli]") {
    const ScratchFolder folder("submit");
    const CommandRun run =
        raystep_in(kSource / "stages/3_intersect",
                   {"submit", "--force", "-o", (folder.path() / "stubs.zip").string()});
    check_run(run, 0,
              {"stages/1_vectors/vectors.cpp +[0-9,]+ bytes",
               "stages/7_recursion/recursion.cpp +[0-9,]+ bytes", "wrote ", "stubs.zip",
               R"(warning: stages/1_vectors/vectors.cpp: still stubs, which )"
               R"(throw NotImplemented \(RAYSTEP_TODO\): dot, cross)"});
}

TEST_CASE("raystep command: submit names the manifest and line of a missing file and exits 1",
          "[cli]") {
    const ScratchFolder folder("submit");
    write_repository(folder.path(), "vectors.cpp\nnorms.cpp\n");
    const CommandRun run = raystep_in(folder.path(), {"submit", "-o", "missing.zip"});
    check_run(run, 1,
              {"^stages/1_vectors/manifest.txt:3: lists norms.cpp, but "
               "stages/1_vectors/norms.cpp does not exist"});
}

// `raystep trace --compare` against a reference trace laid out as a student release has it
// (reference/<scene>.trace.exr beside the scene), written first by the reference build; and the
// same trace beside copies of the scene: at another size, which it no longer fits; with the
// camera moved, an edit the comparison must name; with CRLF line ends, as git on Windows may
// check it out, which is no edit.
namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

// A scratch folder with quad.test and the reference's trace data of it, in reference/; and, where
// `copy` is resized, edited or crlf, that copy of the scene in a folder of that name, with the
// same data beside it.
class TraceFolder {
  public:
    explicit TraceFolder(const std::string& copy = "") : folder_("trace-compare") {
        fs::copy_file(kQuad, path() / "quad.test");
        const std::string scene = raystep::testing::file_text(kQuad);
        const fs::path data = copy.empty() ? "reference" : copy + "/reference";
        if (copy == "resized")
            write_file(path() / copy / "quad.test", replaced(scene, "size 64 48", "size 32 24"));
        if (copy == "edited")
            write_file(path() / copy / "quad.test",
                       replaced(scene, "camera 0 0 4 ", "camera 0 0 4.5 "));
        if (copy == "crlf") write_file(path() / copy / "quad.test", replaced(scene, "\n", "\r\n"));
        const CommandRun run =
            reference_in(path(), {"render", "quad.test", "--view", "full", "-o", "quad.png",
                                  "--trace-data", (data / "quad.trace.exr").string()});
        INFO(run.output());
        REQUIRE(run.exit_code == 0);
        REQUIRE_THAT(
            run.output(),
            PrintsInOrder({R"(wrote .*quad.trace.exr \(the trace data of every pixel\))"}));
    }

    const fs::path& path() const { return folder_.path(); }

  private:
    ScratchFolder folder_;
};

}  // namespace

TEST_CASE(
    "raystep command: trace --compare of the reference's own pixel reports the traces the "
    "same",
    "[cli]") {
    // The scene by its whole path: the reference data is found beside it, wherever the command
    // runs.
    const TraceFolder folder;
    const CommandRun run =
        raystep_in(folder.path(), {"trace", (folder.path() / "quad.test").string(), "20", "30",
                                   "--view", "full", "--compare"});
    check_run(run, 0,
              {"the camera ray's direction ", "the hit primitive +triangle 1 +triangle 1",
               "the full colour", "the traces are the same"});
}

TEST_CASE(
    "raystep command: trace --compare of a scene resized since its data exits 2 naming both "
    "sizes",
    "[cli]") {
    const TraceFolder folder("resized");
    const CommandRun run = raystep_in(
        folder.path(), {"trace", "resized/quad.test", "1", "1", "--view", "full", "--compare"});
    check_run(run, 2,
              {"quad.trace.exr: recorded for a 64 x 48 image, but ",
               "resized/quad.test is 32 x 24: the scene changed since then"});
}

TEST_CASE("raystep command: trace --compare of a pixel outside the image exits 2", "[cli]") {
    const TraceFolder folder;
    const CommandRun run =
        raystep_in(folder.path(), {"trace", "quad.test", "64", "0", "--compare"});
    check_run(run, 2, {R"(pixel \(64, 0\) is outside its 64 x 48 image)"});
}

TEST_CASE(
    "raystep command: trace --compare of a scene edited since its data says a difference "
    "may be the edit's",
    "[cli]") {
    const TraceFolder folder("edited");
    const CommandRun run = raystep_in(
        folder.path(), {"trace", "edited/quad.test", "20", "30", "--view", "full", "--compare"});
    check_run(run, 1,
              {"the scene's files changed since the reference traced them",
               ">> the camera ray's origin"});
}

TEST_CASE(
    "raystep command: trace --compare of the scene with CRLF line ends finds the traces the "
    "same, no edit",
    "[cli]") {
    const TraceFolder folder("crlf");
    const CommandRun run = raystep_in(
        folder.path(), {"trace", "crlf/quad.test", "20", "30", "--view", "full", "--compare"});
    check_run(run, 0, {"crlf/reference/quad.trace.exr\n +quantity", "the traces are the same"});
}

TEST_CASE(
    "raystep command: trace --compare of a scene without reference data exits 2 and says "
    "what it needs",
    "[cli]") {
    check_raystep({"trace", kQuad.string(), "32", "24", "--compare"}, 2,
                  {"no reference trace: the comparison reads ", "good/reference/quad.trace.exr",
                   "raystep-reference render SCENE --view full --trace-data"});
}

// `raystep grade` on a case file whose expectation is wrong (dot is 12, the file says 13): the
// failure with its input, expected and got, and the student's reproduce line; exit 1. Without
// case files it says who makes them and exits 2.
TEST_CASE(
    "raystep command: grade reports a case it fails with its input and reproduce line, "
    "exits 1",
    "[cli]") {
    check_raystep(
        {"grade", "--stage", "1", "--grading",
         (kSource / "app/cli/tests/data/grading-wrong").string()},
        1,
        {"Hidden checks exist and are not run here: 1 check worth 3 points",
         "failed +0 / 3 +stage1.unit: 1 of 2 cases right", R"(input +dot\(1, 2, 3\), \(4, -5, 6\))",
         R"(expected +13 \(within 0\))", "got +12", R"(reproduce +dot\(.1, 2, 3., .4, -5, 6.\))",
         R"(stage1.hidden \(3\))"});
}

TEST_CASE("raystep command: grade without case files says the release writer makes them, exits 2",
          "[cli]") {
    check_raystep({"grade", "--grading", (kSource / "app/cli/tests/data").string()}, 2,
                  {"no public case files in ", "the release writer"});
}

TEST_CASE("raystep command: view --port in hex exits 2: a port is written in decimal", "[cli]") {
    check_raystep({"view", "--port", "0x1F44"}, 2,
                  {"--port: a port is a number from 0 to 65535, not '0x1F44'"});
}

TEST_CASE("raystep command: view --port that is no number exits 2 saying what a port is", "[cli]") {
    check_raystep({"view", "--port", "abc"}, 2,
                  {"--port: a port is a number from 0 to 65535, not 'abc'"});
}
