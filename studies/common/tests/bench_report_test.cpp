#include "studies/common/markdown_table.h"
#include "studies/common/number_text.h"
#include "studies/structures/growth.h"
#include "studies/structures/speed_bar.h"
#include "studies/structures/threshold.h"
#include "studies/structures/workload_table.h"

#include <sstream>

#include "base/testing/catch.h"

using namespace raystep;

namespace {

// A measurement of `rays` rays in `seconds` (one thread) and half that (all threads).
StructureMeasurement measured(const std::string& name, double build_ms, std::size_t rays,
                              double seconds, bool counts) {
    StructureMeasurement m;
    m.name = name;
    m.build_seconds = build_ms * 1e-3;
    RayMeasurement& r = m.ray_sets.emplace_back();
    r.rays = rays;
    r.seconds_one_thread = seconds;
    r.seconds_all_threads = seconds / 2;
    r.coverage = {counts, counts};
    r.stats = {30 * rays, 5 * rays};
    r.answers.resize(rays);
    return m;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

}  // namespace

TEST_CASE("grouped, fixed, three_digits: the tables' numbers", "[bench]") {
    CHECK(grouped(0) == "0");
    CHECK(grouped(999) == "999");
    CHECK(grouped(1212528) == "1,212,528");
    CHECK(fixed(2.345, 1) == "2.3");
    CHECK(three_digits(1234.4) == "1234");
    CHECK(three_digits(12.34) == "12.3");
    CHECK(three_digits(1.234) == "1.23");
    CHECK(three_digits(0.1234) == "0.123");
    CHECK(three_digits(0.0001234) == "0.000123");
    CHECK(three_digits(0.0) == "0.00");
}

TEST_CASE("MarkdownTable: padded columns, numbers right-aligned, a short row's message spans",
          "[bench]") {
    MarkdownTable table({"structure", "ms", "Mrays/s"});
    table.add_row({"BVH SAH", "12.5", "3.00"});
    table.add_row({"grid", "not implemented: stage 4: UniformGrid is a stub"});
    CHECK(table.text() ==
          "| structure |   ms | Mrays/s |\n"
          "| :-------- | ---: | ------: |\n"
          "| BVH SAH   | 12.5 |    3.00 |\n"
          "| grid      | not implemented: stage 4: UniformGrid is a stub |\n");
}

TEST_CASE("workload_table: ratios to the baseline, '-' for what is not counted", "[bench]") {
    StructureMeasurement embree = measured("Embree 3.13.5", 50.0, 1000000, 0.25, false);
    embree.baseline = true;
    StructureMeasurement brute = measured("brute force", 0.0, 1000, 1.0, true);
    brute.builds = false;
    StructureMeasurement grid;
    grid.name = "grid";
    grid.failure = "not implemented: stage 4: UniformGrid";
    const std::vector<StructureMeasurement> ms{measured("BVH SAH", 100.0, 1000000, 0.5, true), grid,
                                               brute, embree};

    const std::vector<std::string> lines = lines_of(workload_table(ms, 0, 2));
    REQUIRE(lines.size() == 6);
    CHECK(
        lines[0] ==
        "| structure     | build ms | x Embree | Mrays/s, 1 thread | x Embree | Mrays/s, 2 threads "
        "| x Embree | nodes/ray | tests/ray |");
    // 100 ms against 50: 2; 2 Mrays/s against 4: 0.5, on both thread counts
    CHECK(
        lines[2] ==
        "| BVH SAH       |      100 |     2.00 |              2.00 |    0.500 |               4.00 "
        "|    0.500 |      30.0 |       5.0 |");
    CHECK(lines[3] == "| grid          | not implemented: stage 4: UniformGrid |");
    CHECK(
        lines[4] ==
        "| brute force   |        - |        - |           0.00100 | 0.000250 |            0.00200 "
        "| 0.000250 |      30.0 |       5.0 |");
    CHECK(
        lines[5] ==
        "| Embree 3.13.5 |     50.0 |     1.00 |              4.00 |     1.00 |               8.00 "
        "|     1.00 |         - |         - |");
}

TEST_CASE("workload_table: without a baseline, no ratio columns", "[bench]") {
    const std::vector<std::string> lines =
        lines_of(workload_table({measured("BVH SAH", 10.0, 100, 1.0, true)}, 0, 1));
    CHECK(
        lines[0] ==
        "| structure | build ms | Mrays/s, 1 thread | Mrays/s, 1 thread | nodes/ray | tests/ray |");
}

TEST_CASE("workload_notes: the subsample, the baseline's one-thread build", "[bench]") {
    StructureMeasurement brute = measured("brute force", 0.0, 889, 1.0, true);
    brute.ray_sets[0].stride = 295;
    StructureMeasurement embree = measured("Embree 3.13.5", 50.0, 1000, 0.25, false);
    embree.baseline = true;
    embree.single_thread_build_seconds = 0.08;
    const std::vector<std::string> notes =
        workload_notes({measured("BVH SAH", 100.0, 1000, 0.5, true), brute, embree}, 0, 262144);
    REQUIRE(notes.size() == 3);
    CHECK(notes[0] ==
          "brute force: on 889 of the 262,144 rays (every 295th), to keep within its budget of "
          "primitive tests");
    CHECK(notes[1] ==
          "Embree 3.13.5 built on one thread: 80.0 ms; BVH SAH's build takes 1.25 times that");
    CHECK_THAT(notes[2], Catch::Matchers::StartsWith("cross-check: the same hits as BVH SAH"));
}

TEST_CASE("growth_table: build ms and Mrays/s per structure, '-' where skipped", "[bench]") {
    StructureMeasurement skipped;
    skipped.name = "brute force";
    skipped.failure = "skipped: 16,384 primitives, over its limit of 4,096";
    GrowthRow row{16384, {measured("BVH SAH", 12.0, 1000000, 0.5, true), skipped}};
    const std::vector<std::string> lines = lines_of(growth_table({row}));
    REQUIRE(lines.size() == 3);
    CHECK(lines[0] ==
          "| triangles | BVH SAH build ms | BVH SAH Mrays/s | brute force build ms | brute force "
          "Mrays/s |");
    CHECK(lines[2] ==
          "| 16,384    |             12.0 |            2.00 |                    - |               "
          "    - |");
}

TEST_CASE("growth_table: a stub's cells read '-' and its message follows the table", "[bench]") {
    StructureMeasurement stub;
    stub.name = "grid";
    stub.failure = "not implemented: stage 4: UniformGrid";
    const GrowthRow small{1024, {stub}};
    const GrowthRow large{4096, {stub}};
    const std::vector<std::string> lines = lines_of(growth_table({small, large}));
    REQUIRE(lines.size() == 6);
    CHECK(lines[3] == "| 4,096     |             - |            - |");
    // A blank line, or Markdown would read the message as one more row
    CHECK(lines[4].empty());
    CHECK(lines[5] == "- grid: not implemented: stage 4: UniformGrid");
}

TEST_CASE("threshold_report: the table and the n from which the BVH pays", "[bench]") {
    ThresholdCurve curve;
    curve.kind = "spheres";
    curve.points = {{4, 50.0, 60.0, 3.0, 60.0}, {8, 90.0, 70.0, 6.0, 70.0}};
    curve.bvh_pays_from = 8;
    ThresholdCurve stub;
    stub.kind = "triangles";
    stub.failure = "not implemented: stage 4: Bvh";
    const std::string text = threshold_report({curve, stub}, ThresholdOptions{});
    CHECK_THAT(text, Catch::Matchers::Contains("| 8   |               90.0 |             70.0 |"));
    CHECK_THAT(text, Catch::Matchers::Contains("The BVH pays from n = 8 spheres on"));
    CHECK_THAT(text, Catch::Matchers::Contains("triangles:\n\nnot implemented: stage 4: Bvh"));
}

TEST_CASE("bvh_pays_from: the smallest n from which the BVH stays cheaper", "[bench]") {
    // Cheaper at 4 by chance, dearer at 8, cheaper from 16 on: 16
    const std::vector<ThresholdPoint> points{{2, 10, 0, 0, 20},
                                             {4, 20, 0, 0, 19},
                                             {8, 30, 0, 0, 31},
                                             {16, 50, 0, 0, 40},
                                             {32, 90, 0, 0, 45}};
    CHECK(bvh_pays_from(points) == std::optional<std::size_t>(16));
    CHECK_FALSE(bvh_pays_from({{2, 10, 0, 0, 20}}));
    CHECK_FALSE(bvh_pays_from({}));
}

TEST_CASE("speed_bar_lines: each goal's ratio and verdict, on the bunny only", "[bench]") {
    // Primary: 2 Mrays/s against 2 (met); incoherent: 1 against 4 (not met); build 100 ms
    // against 40 (2.5 times: not met)
    StructureMeasurement ours = measured("BVH SAH", 100.0, 1000000, 0.5, true);
    ours.ray_sets.push_back(ours.ray_sets[0]);
    ours.ray_sets[1].seconds_one_thread = 1.0;
    StructureMeasurement theirs = measured("Embree 3.13.5", 40.0, 1000000, 0.5, false);
    theirs.baseline = true;
    theirs.ray_sets.push_back(theirs.ray_sets[0]);
    theirs.ray_sets[1].seconds_one_thread = 0.25;
    const std::vector<RaySet> sets{{"bunny-primary", "", {}}, {"bunny-incoherent", "", {}}};

    const std::vector<std::string> lines = speed_bar_lines("bunny", {ours, theirs}, sets);
    REQUIRE(lines.size() == 3);
    CHECK(lines[0] ==
          "speed bar, BVH SAH against Embree 3.13.5: primary rays on one thread 1.00x (goal: at "
          "least 0.8x): met");
    CHECK(lines[1] ==
          "speed bar, BVH SAH against Embree 3.13.5: incoherent rays on one thread 0.250x (goal: "
          "at least 0.5x): NOT MET");
    CHECK(lines[2] ==
          "speed bar, BVH SAH against Embree 3.13.5: build 2.50x (goal: at most 2.0x): NOT MET");
    CHECK(speed_bar_lines("spheres", {ours, theirs}, sets).empty());
    CHECK(speed_bar_lines("bunny", {ours}, sets).empty());
}

TEST_CASE("speed_bar_lines: not judged against a baseline held to an instruction set", "[bench]") {
    const StructureMeasurement ours = measured("BVH SAH", 100.0, 1000000, 0.5, true);
    StructureMeasurement theirs =
        measured("Embree 3.13.5 (max_isa=sse2)", 40.0, 1000000, 0.5, false);
    theirs.baseline = true;
    theirs.isa = "sse2";
    const std::vector<RaySet> sets{{"bunny-primary", "", {}}};

    const std::vector<std::string> lines = speed_bar_lines("bunny", {ours, theirs}, sets);
    REQUIRE(lines.size() == 1);
    CHECK(lines[0] ==
          "speed bar: not judged against Embree 3.13.5 (max_isa=sse2): the goals are set against "
          "the baseline at the best instructions the processor has");
}
