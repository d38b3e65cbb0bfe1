#include "studies/epsilon/epsilon_study.h"

#include <string>

#include "base/testing/catch.h"
#include "studies/tests/text_occurrences.h"

using namespace raystep;
using raystep::testing::occurrences;

namespace {

EpsilonSceneResult result_for(const std::string& scene) {
    EpsilonSceneResult r;
    r.scene = "scenes/stage6/" + scene + ".test";
    r.lit = 1000;
    r.shadowed = 200;
    r.epsilons = {1e-3, 1e-2};
    r.along_ray = {{0, 0}, {3, 40}};
    r.along_normal = {{1, 0}, {12, 150}};
    r.error_bound = {0, 0};
    return r;
}

}  // namespace

TEST_CASE("study_epsilons: every power of ten from 1e-14 to 1e-1", "[bench]") {
    const std::vector<double> epsilons = study_epsilons();
    REQUIRE(epsilons.size() == 14);
    CHECK(epsilons.front() == 1e-14);
    CHECK(epsilons.back() == 1e-1);
}

TEST_CASE("epsilon_table: a row per epsilon and one for error-bound", "[bench]") {
    const std::string table = epsilon_table(result_for("acne-scale-1"));
    CHECK(table.find("| 1e-3 ") != std::string::npos);
    CHECK(table.find("| 1e-2        |              3 |              40 |                12 |       "
                     "         150 |") != std::string::npos);
    CHECK(table.find("| error-bound |              0 |               0 | (no epsilon)") !=
          std::string::npos);
}

TEST_CASE("epsilon_notes: the pixels counted and those left out, or why it stopped", "[bench]") {
    EpsilonSceneResult r = result_for("acne-scale-1");
    r.undecided = 3;
    CHECK(epsilon_notes(r) ==
          "1,000 pixels exactly lit, 200 exactly in shadow; left out: 3 within "
          "1e-12 of an edge, 0 where the eye ray's primitive differs from the "
          "exact one");
    r.stopped = "stage 6: shadow_ray is not implemented yet";
    CHECK(epsilon_notes(r) == "stopped: stage 6: shadow_ray is not implemented yet");
}

TEST_CASE("epsilon_chart_svg: a panel per scene with four lines and error-bound in words",
          "[bench]") {
    const std::string svg =
        epsilon_chart_svg({result_for("acne-scale-1e-3"), result_for("acne-scale-1")});
    CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
    CHECK(svg.find("</svg>") != std::string::npos);
    CHECK(occurrences(svg, "<polyline") == 8);
    CHECK(svg.find(">acne-scale-1e-3</text>") != std::string::npos);
    CHECK(occurrences(svg, "error-bound: 0 acne, 0 leaks") == 2);
}
