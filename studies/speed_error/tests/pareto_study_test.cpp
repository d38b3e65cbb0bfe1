// The speed-against-error study (`raystep-reference bench --pareto`): its scoring, the float
// variants it measures, its JSON. No time is asserted.

#include "studies/speed_error/pareto_study.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/check/case_file.h"
#include "base/testing/catch.h"
#include "studies/speed_error/pareto_json.h"
#include "studies/speed_error/pareto_reference_methods.h"

using namespace raystep;

namespace {

// Timing samples short enough for a test; the numbers are not looked at.
const ParetoTiming kQuick{0.0005, 1};

CaseFamily hand_computed_family() {
    return read_case_file(std::string(RAYSTEP_TEST_DATA) + "/cases/axis-aligned.cases").at(0);
}

CaseFamily public_family(const std::string& name) {
    return read_case_file(std::string(RAYSTEP_SOURCE_DIR) + "/stages/3_intersect/cases/" + name +
                          ".cases")
        .at(0);
}

std::optional<Hit> never_hits(const Ray&, const Triangle&) {
    return std::nullopt;
}

ParetoMethod blind_triangle_test() {
    ParetoMethod entry{{"never_hits", Stage3Method::Kind::triangle}, "blind", "double"};
    entry.method.triangle = never_hits;
    return entry;
}

const ParetoMethod& reference_method(const std::string& name) {
    static const std::vector<ParetoMethod> methods = reference_pareto_methods();
    const auto found = std::find_if(methods.begin(), methods.end(),
                                    [&](const ParetoMethod& m) { return m.method.name == name; });
    REQUIRE(found != methods.end());
    return *found;
}

// The cases where a test that reports no triangle hit is wrong against the exact answer: the ray
// meets a triangle exactly, near a boundary or not (the study counts what the grading forgives).
std::size_t cases_with_a_triangle_hit(const CaseFamily& family) {
    std::size_t count = 0;
    for (const RayCase& ray_case : family.cases) {
        const bool hit = std::any_of(
            ray_case.primitives.begin(), ray_case.primitives.end(), [&](const CasePrimitive& p) {
                return std::holds_alternative<Triangle>(p.shape) && p.expected.hit;
            });
        count += hit;
    }
    return count;
}

}  // namespace

TEST_CASE("measure_pareto_family: a test that never hits misses every exact triangle hit",
          "[pareto]") {
    const CaseFamily family = hand_computed_family();
    const ParetoFamily result = measure_pareto_family(family, {blind_triangle_test()}, kQuick);
    REQUIRE(result.points.size() == 1);
    const ParetoPoint& blind = result.points[0];
    CHECK(blind.false_hits == 0);
    CHECK(blind.false_misses == cases_with_a_triangle_hit(family));
    CHECK(blind.false_misses > 0);
    CHECK(blind.wrong_share() > 0.0);
    CHECK(blind.mrays_per_second > 0.0);
}

TEST_CASE("measure_pareto_family: the reference tests are right on the hand-computed cases",
          "[pareto]") {
    const ParetoFamily result =
        measure_pareto_family(hand_computed_family(), reference_pareto_methods(), kQuick);
    CHECK(result.points.size() == reference_pareto_methods().size());
    // The study counts against the exact answer, near a boundary too: a float test may hit the
    // one case that passes within rounding of an edge and misses it exactly; a double test does
    // not.
    for (const ParetoPoint& point : result.points) {
        CAPTURE(point.function);
        CHECK(point.cases > 0);
        CHECK(point.false_hits <= (point.precision == "float" ? 1u : 0u));
        CHECK(point.false_misses == 0);
    }
}

TEST_CASE("measure_pareto_family: a method that tests no primitive of the family is left out",
          "[pareto]") {
    const ParetoFamily result = measure_pareto_family(
        public_family("random-spheres"),
        {blind_triangle_test(), reference_method("intersect_sphere")}, kQuick);
    REQUIRE(result.points.size() == 1);
    CHECK(result.points[0].function == "intersect_sphere");
}

TEST_CASE("float variants: the same hits as their double namesakes, t within float rounding",
          "[pareto]") {
    // Random triangles, spheres and planes stay far from every boundary in float as in double, so
    // the answers must agree case by case; t differs by float's rounding of the inputs and the
    // arithmetic, a few float ulps (2^-24 relative each), far below 1e-4.
    const std::pair<const char*, const char*> pairs[] = {
        {"intersect_triangle_projection", "random-triangles"},
        {"intersect_triangle_halfspaces", "random-triangles"},
        {"intersect_triangle_cramer", "random-triangles"},
        {"intersect_triangle_moller_trumbore", "random-triangles"},
        {"intersect_triangle_watertight", "random-triangles"},
        {"intersect_sphere_textbook", "random-spheres"},
        {"intersect_sphere_stable_roots", "random-spheres"},
        {"intersect_sphere", "random-spheres"},
        {"intersect_plane", "random-planes"},
    };
    for (const auto& [name, family_name] : pairs) {
        const ParetoMethod& in_double = reference_method(name);
        const ParetoMethod& in_float = reference_method(std::string(name) + "_float");
        CHECK(in_float.precision == "float");
        std::size_t hits = 0;
        for (const RayCase& ray_case : public_family(family_name).cases) {
            const CaseAnswer d = run_method(in_double.method, ray_case);
            const CaseAnswer f = run_method(in_float.method, ray_case);
            for (std::size_t k = 0; k < d.hits.size(); ++k) {
                CAPTURE(name, k);
                REQUIRE(d.hits[k].has_value() == f.hits[k].has_value());
                if (!d.hits[k]) continue;
                ++hits;
                CHECK(std::abs(f.hits[k]->t - d.hits[k]->t) <= 1e-4 * std::abs(d.hits[k]->t));
                CHECK(f.hits[k]->t != d.hits[k]->t);
            }
        }
        CHECK(hits > 10);
    }
}

TEST_CASE("pareto_json: the families read back as they were written", "[pareto]") {
    ParetoFamily family;
    family.name = "shared-edges";
    family.description = "rays through shared edges";
    family.cases = 100;
    ParetoPoint point;
    point.label = "Cramer";
    point.precision = "float";
    point.function = "intersect_triangle_cramer_float";
    point.cases = 100;
    point.false_hits = 1;
    point.false_misses = 12;
    point.t_ulps_median = 4.4e8;
    point.t_ulps_p99 = 9.6e9;
    point.t_ulps_max = 1.1e10;
    point.mrays_per_second = 54.0;
    family.points = {point};

    const nlohmann::json json = pareto_json("a machine", "today", {family}, {});
    CHECK(json.at("study") == "pareto");
    CHECK(json.at("families").at(0).at("points").at(0).at("wrong_share") == 0.13);
    const std::vector<ParetoFamily> back = pareto_families_from_json(json);
    REQUIRE(back.size() == 1);
    CHECK(back[0].name == family.name);
    CHECK(back[0].cases == 100);
    REQUIRE(back[0].points.size() == 1);
    const ParetoPoint& read = back[0].points[0];
    CHECK(read.function == point.function);
    CHECK(read.false_misses == 12);
    CHECK(read.t_ulps_p99 == point.t_ulps_p99);
    CHECK(read.mrays_per_second == point.mrays_per_second);
}
