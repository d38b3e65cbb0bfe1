#include "studies/epsilon/epsilon_study.h"

#include <string>

#include <nlohmann/json.hpp>

#include "base/testing/catch.h"

using namespace raystep;

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

TEST_CASE("epsilon_json: a scene per result by its stem, acne and leaks per epsilon and rule",
          "[bench]") {
    const nlohmann::json json =
        epsilon_json({result_for("acne-scale-1e-3"), result_for("acne-scale-1")});
    CHECK(json.at("study") == "epsilon");
    REQUIRE(json.at("scenes").size() == 2);
    const nlohmann::json& scene = json.at("scenes").at(1);
    CHECK(scene.at("scene") == "acne-scale-1");
    CHECK(scene.at("lit") == 1000);
    CHECK(scene.at("epsilons") == nlohmann::json::array({1e-3, 1e-2}));
    CHECK(scene.at("along_ray").at(1) == nlohmann::json{{"acne", 3}, {"leaks", 40}});
    CHECK(scene.at("along_normal").at(1) == nlohmann::json{{"acne", 12}, {"leaks", 150}});
    CHECK(scene.at("error_bound") == nlohmann::json{{"acne", 0}, {"leaks", 0}});
}
