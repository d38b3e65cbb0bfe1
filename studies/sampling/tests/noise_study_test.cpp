#include "studies/sampling/noise_study.h"

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "base/testing/catch.h"

using namespace raystep;

namespace {

// A curve whose RMSE is `first` / N^`falls` at N = 1, 4, 16, two runs each.
NoiseCurve power_curve(const std::string& method, SamplingKind kind, double first, double falls) {
    NoiseCurve curve{method, kind, {}};
    for (const int n : {1, 4, 16}) {
        curve.points.push_back({n, 2, 0.001 * n, first / std::pow(n, falls), 0.001});
    }
    return curve;
}

NoiseScene light_scene(const NoiseCurve& stratified, const NoiseCurve& random) {
    return {"soft-shadows", "light samples", "a test scene", {stratified, random}};
}

}  // namespace

TEST_CASE("noise_findings: random falling and stratified below it both hold", "[bench]") {
    const std::vector<NoiseFinding> findings =
        noise_findings({light_scene(power_curve("stratified", SamplingKind::stratified, 0.1, 0.75),
                                    power_curve("random", SamplingKind::random, 0.1, 0.5))});
    REQUIRE(findings.size() == 2);
    CHECK(findings[0].text ==
          "random light samples: the RMSE falls at every larger count on soft-shadows");
    CHECK(findings[0].holds);
    CHECK(findings[1].text ==
          "stratified below random at 16 light samples on soft-shadows (RMSE 0.0125 against "
          "0.0250)");
    CHECK(findings[1].holds);
}

TEST_CASE("noise_findings: a random curve that stops falling, or a stratified one above it, fails",
          "[bench]") {
    NoiseCurve random = power_curve("random", SamplingKind::random, 0.1, 0.5);
    random.points[2].rmse = random.points[1].rmse;  // flat from 4 to 16: biased, or one seed
    const NoiseCurve worse = power_curve("stratified", SamplingKind::stratified, 0.2, 0.5);
    const std::vector<NoiseFinding> findings = noise_findings({light_scene(worse, random)});
    REQUIRE(findings.size() == 2);
    CHECK_FALSE(findings[0].holds);
    CHECK_FALSE(findings[1].holds);
}

TEST_CASE("noise_findings: a scene without a random curve adds nothing", "[bench]") {
    const NoiseScene scene{
        "stripes", "pixel samples", "", {power_curve("regular", SamplingKind::regular, 0.1, 0.5)}};
    CHECK(noise_findings({scene}).empty());
}

TEST_CASE("noise_slope: the fitted exponent of the curve's mean RMSE", "[bench]") {
    CHECK(noise_slope(power_curve("random", SamplingKind::random, 0.3, 0.5)) == Approx(-0.5));
    CHECK(noise_slope(power_curve("jittered", SamplingKind::stratified, 0.3, 0.75)) ==
          Approx(-0.75));
}

TEST_CASE("noise_table: a row per point and each curve's slope", "[bench]") {
    const std::string table =
        noise_table(light_scene(power_curve("stratified", SamplingKind::stratified, 0.1, 0.75),
                                power_curve("random", SamplingKind::random, 0.1, 0.5)));
    CAPTURE(table);
    CHECK(table.find("| method     | samples | runs | CPU ms per render |") == 0);
    CHECK(table.find("| random     |      16 |    2 |              16.0 | 0.0250 | 0.00100 |") !=
          std::string::npos);
    CHECK(table.find("slope of log RMSE against log samples: stratified -0.75, random -0.50") !=
          std::string::npos);
}

TEST_CASE("noise_json: a scene per panel, each curve's kind, slope and points", "[bench]") {
    const NoiseScene light =
        light_scene(power_curve("stratified", SamplingKind::stratified, 0.1, 0.75),
                    power_curve("random", SamplingKind::random, 0.1, 0.5));
    const nlohmann::json json = noise_json("a machine", "today", {light});
    CHECK(json.at("study") == "sampling-noise");
    CHECK(json.at("machine") == "a machine");
    REQUIRE(json.at("scenes").size() == 1);
    CHECK(json.at("scenes").at(0).at("sampled") == "light samples");
    const nlohmann::json& random = json.at("scenes").at(0).at("curves").at(1);
    CHECK(random.at("kind") == "random");
    CHECK(random.at("slope").get<double>() == Approx(-0.5));
    REQUIRE(random.at("points").size() == 3);
    CHECK(random.at("points").at(2).at("samples") == 16);
    CHECK(random.at("points").at(2).at("rmse").get<double>() == Approx(0.025));
}
