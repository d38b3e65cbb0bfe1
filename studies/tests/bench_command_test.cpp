// `raystep bench` as an instructor meets it: a smoke test of each study on its smallest workload,
// and bad options as command-line errors. No time is asserted: the bench prints ratios, it does
// not judge them. The tests tagged [measurement] run a study's workload: the sanitizer run leaves
// them out (labelled measurement, studies/tests/CMakeLists.txt).

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "base/testing/catch.h"
#include "base/testing/command_run.h"
#include "base/testing/scratch_folder.h"

using raystep::testing::CommandRun;
using raystep::testing::ScratchFolder;

namespace fs = std::filesystem;

namespace {

const fs::path kData = RAYSTEP_TEST_DATA;

// `program` with `arguments` in a scratch folder of its own, judged by check_run.
void check_program(const std::string& program, std::vector<std::string> arguments, int exit_code,
                   std::vector<std::string> patterns) {
    arguments.insert(arguments.begin(), program);
    raystep::testing::check_command(arguments, exit_code, std::move(patterns));
}

void check_raystep(std::vector<std::string> arguments, int exit_code,
                   std::vector<std::string> patterns) {
    check_program(RAYSTEP_PROGRAM, std::move(arguments), exit_code, std::move(patterns));
}

void check_reference(std::vector<std::string> arguments, int exit_code,
                     std::vector<std::string> patterns) {
    check_program(RAYSTEP_REFERENCE_PROGRAM, std::move(arguments), exit_code, std::move(patterns));
}

}  // namespace

TEST_CASE("raystep command: bench --quick on the spheres prints a table of every structure",
          "[cli][measurement]") {
    check_raystep(
        {"bench", "--quick", "--workload", "spheres"}, 0,
        {"### spheres-primary", R"([|] structure +[|] build ms +[|])", R"([|] BVH SAH +[|])",
         R"([|] grid +[|])", "- cross-check: the same hits as BVH SAH"});
}

TEST_CASE("raystep command: bench with an unknown workload exits 2 and lists the workloads",
          "[cli]") {
    check_raystep({"bench", "--workload", "teapot"}, 2, {"bunny-primary"});
}

TEST_CASE("raystep command: bench with a zero thread count exits 2", "[cli]") {
    check_raystep({"bench", "--threads", "0"}, 2, {"threads"});
}

TEST_CASE(
    "raystep command: bench --epsilon: error-bound has no acne and no leaks on every acne "
    "scene",
    "[cli][measurement]") {
    check_raystep({"bench", "--epsilon"}, 0,
                  {"acne-scale-1e-3.test", R"([|] error-bound +[|] +0 [|] +0 [|])",
                   "acne-scale-1.test", R"([|] error-bound +[|] +0 [|] +0 [|])",
                   "acne-scale-1e4.test", R"([|] error-bound +[|] +0 [|] +0 [|])"});
}

TEST_CASE("raystep command: bench --scale --quick prints the scenes' costs and a line per bar",
          "[cli][measurement]") {
    check_raystep(
        {"bench", "--scale", "--quick"}, 0,
        {R"([|] spheres-1000 +[|])", R"([|] bunnies-1000 +[|])",
         "against the 127,408-triangle scene", R"(x [(]bar: at most 1[.]50x[)] (met|MISSED))",
         R"(instanced bunnies against one, memory: ([0-9.]+x|not measured))"});
}

TEST_CASE("raystep command: bench --json without --epsilon exits 2", "[cli]") {
    check_raystep({"bench", "--json", "study.json"}, 2, {"--json requires --epsilon"});
}

// The sampling study, quick: its findings are what correct stage-8 code must show (random samples'
// RMSE falls with N; stratified beats random at the largest N on every scene), and its figures.
TEST_CASE(
    "raystep command: bench --sampling --quick: random noise falls, stratified is below "
    "random",
    "[cli][measurement]") {
    check_raystep(
        {"bench", "--sampling", "--quick", "--json", "sampling-noise.json"}, 0,
        {"### stripes, pixel samples", R"([|] jittered +[|] +16 [|])", "### glass-cube",
         "### soft-shadows, light samples", R"([|] stratified +[|] +16 [|])",
         "- random pixel samples: the RMSE falls at every larger count on stripes: yes",
         R"(- jittered below random at 16 pixel samples on stripes [(]RMSE [0-9.]+ against )"
         R"([0-9.]+[)]: yes)",
         "- random pixel samples: the RMSE falls at every larger count on glass-cube: yes",
         "- jittered below random at 16 pixel samples on glass-cube ", ": yes",
         "- random light samples: the RMSE falls at every larger count on soft-shadows: yes",
         "- stratified below random at 16 light samples on soft-shadows ", ": yes",
         "- the figures: ", "sampling-noise.json"});
}

TEST_CASE("raystep command: bench --sampling with --workload exits 2", "[cli]") {
    check_raystep({"bench", "--sampling", "--workload", "spheres"}, 2,
                  {"--workload excludes --sampling"});
}

TEST_CASE("raystep command: bench --cases without --pareto exits 2", "[cli]") {
    check_raystep({"bench", "--cases", (kData / "cases/axis-aligned.cases").string()}, 2,
                  {"--cases requires --pareto"});
}

TEST_CASE("raystep command: bench --pareto in raystep names raystep-reference, which has the study",
          "[cli]") {
    check_raystep({"bench", "--pareto"}, 1, {"run raystep-reference bench --pareto"});
}

TEST_CASE(
    "raystep command: bench --embree-isa in raystep names raystep-reference, which has Embree",
    "[cli]") {
    check_raystep({"bench", "--embree-isa", "sse2", "--workload", "spheres"}, 1,
                  {"Embree is linked only into raystep-reference"});
}

TEST_CASE(
    "raystep command: bench --embree-isa with an unknown instruction set exits 2 and lists "
    "them",
    "[cli]") {
    check_raystep({"bench", "--embree-isa", "avx9"}, 2, {"sse2,sse4.2,avx,avx2,avx512"});
}

TEST_CASE("raystep command: bench --pareto with a bad case file reports file:line and exits 1",
          "[cli]") {
    check_reference({"bench", "--pareto", "--quick", "--cases",
                     (kData / "cases/bad/missing-end.cases").string(), "--out", "pareto-bad"},
                    1, {"missing-end.cases:3: case 0 has no 'end'"});
}

TEST_CASE("raystep command: bench --pareto writes its families and offset rules as JSON",
          "[cli][measurement]") {
    check_reference(
        {"bench", "--pareto", "--quick", "--cases", (kData / "cases/axis-aligned.cases").string(),
         "--out", "pareto"},
        0,
        {R"([|] axis-aligned +[|] +watertight +[|] +float +[|])",
         R"([|] acne-scale-1e4 +[|] +error-bound +[|])", "- the figures: ", "pareto/pareto.json"});
}

#if RAYSTEP_HAVE_EMBREE
TEST_CASE("raystep command: bench --embree-isa sse2 measures Embree held to SSE2 as the baseline",
          "[cli][measurement]") {
    check_reference({"bench", "--quick", "--workload", "spheres-primary", "--embree-isa", "sse2"},
                    0, {R"([|] Embree [0-9.]+ [(]max_isa=sse2[)] +[|] +[0-9.]+ [|] +1[.]00 [|])"});
}
#endif

// The charts are drawn from the studies' JSON by scripts/draw-charts.py, which names a file that
// is not a study's.
TEST_CASE("charts: draw-charts.py names a JSON file that is not a study's", "[cli]") {
    const ScratchFolder folder("charts");
    std::ofstream(folder.path() / "not-a-study.json") << "{\"families\": []}\n";
    const CommandRun run = raystep::testing::run_command(
        {RAYSTEP_CHART_PYTHON, RAYSTEP_SOURCE_DIR "/scripts/draw-charts.py", "not-a-study.json"},
        folder.path());
    raystep::testing::check_run(run, 2, {"not-a-study.json: not the JSON of a study"});
}
