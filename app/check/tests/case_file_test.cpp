#include "app/check/case_file.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "base/errors/input_error.h"
#include "base/testing/catch.h"
#include "base/testing/vec3_matchers.h"

using namespace raystep;

namespace {

const std::filesystem::path kCases = std::filesystem::path(RAYSTEP_TEST_DATA) / "cases";
constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::vector<CaseFamily> parse(const std::string& text) {
    return parse_case_file(text, "t.cases");
}

std::string written(const std::vector<CaseFamily>& families) {
    std::ostringstream out;
    write_case_file(out, families);
    return out.str();
}

std::uint64_t bits(double value) {
    std::uint64_t b;
    std::memcpy(&b, &value, sizeof b);
    return b;
}

// The same bits, or both NaN (an absent field reads back as the default NaN).
bool same(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || bits(a) == bits(b);
}

bool same(const Vec3& a, const Vec3& b) {
    return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

void check_same(const Expectation& a, const Expectation& b) {
    CHECK(a.hit == b.hit);
    CHECK(a.near_boundary == b.near_boundary);
    CHECK(same(a.t, b.t));
    CHECK(same(a.t_tolerance, b.t_tolerance));
    CHECK(same(a.normal, b.normal));
    CHECK(same(a.normal_tolerance, b.normal_tolerance));
    CHECK(same(a.beta, b.beta));
    CHECK(same(a.gamma, b.gamma));
    CHECK(same(a.barycentric_tolerance, b.barycentric_tolerance));
    CHECK(same(a.t_alternative, b.t_alternative));
    CHECK(same(a.normal_alternative, b.normal_alternative));
}

void check_same(const CaseShape& a, const CaseShape& b) {
    REQUIRE(a.index() == b.index());
    if (const auto* s = std::get_if<Sphere>(&a)) {
        CHECK(same(s->center, std::get<Sphere>(b).center));
        CHECK(same(s->radius, std::get<Sphere>(b).radius));
    } else if (const auto* t = std::get_if<Triangle>(&a)) {
        CHECK(same(t->p0, std::get<Triangle>(b).p0));
        CHECK(same(t->p1, std::get<Triangle>(b).p1));
        CHECK(same(t->p2, std::get<Triangle>(b).p2));
    } else {
        CHECK(same(std::get<Plane>(a).point, std::get<Plane>(b).point));
        CHECK(same(std::get<Plane>(a).normal, std::get<Plane>(b).normal));
    }
}

void check_same(const std::vector<CaseFamily>& a, const std::vector<CaseFamily>& b) {
    REQUIRE(a.size() == b.size());
    for (std::size_t f = 0; f < a.size(); ++f) {
        CAPTURE(f);
        CHECK(a[f].name == b[f].name);
        CHECK(a[f].seed == b[f].seed);
        CHECK(a[f].description == b[f].description);
        REQUIRE(a[f].cases.size() == b[f].cases.size());
        for (std::size_t c = 0; c < a[f].cases.size(); ++c) {
            CAPTURE(c);
            const RayCase& x = a[f].cases[c];
            const RayCase& y = b[f].cases[c];
            CHECK(x.index == y.index);
            CHECK(x.watertight == y.watertight);
            CHECK(same(x.ray.origin, y.ray.origin));
            CHECK(same(x.ray.direction, y.ray.direction));
            CHECK(same(x.ray.t_min, y.ray.t_min));
            CHECK(same(x.ray.t_max, y.ray.t_max));
            REQUIRE(x.primitives.size() == y.primitives.size());
            for (std::size_t p = 0; p < x.primitives.size(); ++p) {
                CAPTURE(p);
                check_same(x.primitives[p].shape, y.primitives[p].shape);
                check_same(x.primitives[p].expected, y.primitives[p].expected);
            }
        }
    }
}

Expectation measured_hit(double t, const Vec3& normal) {
    Expectation e;
    e.hit = true;
    e.t = t;
    e.t_tolerance = 1e-300;
    e.normal = normal;
    e.normal_tolerance = 0.1;
    return e;
}

// Values whose text must carry every bit: not exact in binary (0.1, 1/3), tiny and subnormal,
// huge, negative zero, and an infinite t_max.
std::vector<CaseFamily> tricky_families() {
    RayCase first;
    first.index = 12;
    first.watertight = true;
    first.ray = {{0.1, -0.0, 1e300}, {1e-300, 1.0 / 3.0, -5e-324}, -0.0, kInfinity};
    Expectation triangle_hit = measured_hit(0.1, {-0.0, 0.6, 0.8});
    triangle_hit.near_boundary = true;
    triangle_hit.beta = 1.0 / 3.0;
    triangle_hit.gamma = -0.0;
    triangle_hit.barycentric_tolerance = 2.2250738585072014e-308;
    first.primitives.push_back(
        {Triangle{{0.1, 0.2, 0.3}, {1e300, -1e-300, 0.0}, {-0.0, 4.9e-324, 1.0 / 7.0}},
         triangle_hit});
    first.primitives.push_back({Plane{{1e-300, 0.0, -0.0}, {0.1, 0.7, 1e300}}, Expectation{}});

    RayCase second;
    second.index = 0;
    second.ray = {{1.0, 2.0, 3.0}, {0.0, 0.0, -1.0}, 0.1, 1e300};
    Expectation sphere_hit = measured_hit(1.0 / 3.0, {0.0, 0.0, 1.0});
    sphere_hit.t_alternative = 0.30000000000000004;
    sphere_hit.normal_alternative = {0.0, 0.0, -1.0};
    second.primitives.push_back({Sphere{{0.1, -0.0, 1e300}, 1e-300}, sphere_hit});
    Expectation near_miss = measured_hit(1e300, {1.0, 0.0, 0.0});
    near_miss.hit = false;
    near_miss.near_boundary = true;
    second.primitives.push_back({Sphere{{0.0, 0.0, 0.0}, 0.1}, near_miss});

    CaseFamily tricky{"tricky-values", 2147483647, "internal  white   space  is kept", {}};
    tricky.cases = {first, second};
    CaseFamily plain{"no-description", 0, "", {second}};
    return {tricky, plain};
}

struct BadFile {
    const char* why;
    std::string text;
    std::string message;
};

}  // namespace

TEST_CASE("read_case_file: reads the hand-computed file", "[app]") {
    const std::vector<CaseFamily> families = read_case_file(kCases / "axis-aligned.cases");
    REQUIRE(families.size() == 2);

    const CaseFamily& axis = families[0];
    CHECK(axis.name == "axis-aligned");
    CHECK(axis.seed == 1);
    CHECK(axis.description ==
          "hand-computed: rays along the axes, every kind of primitive, hits and misses");
    REQUIRE(axis.cases.size() == 6);

    const RayCase& first = axis.cases[0];
    CHECK(first.index == 0);
    CHECK_FALSE(first.watertight);
    CHECK(first.ray.origin == Vec3(0.25, 0.5, 5.0));
    CHECK(first.ray.direction == Vec3(0.0, 0.0, -1.0));
    CHECK(first.ray.t_min == 0.0);
    CHECK(first.ray.t_max == kInfinity);
    REQUIRE(first.primitives.size() == 4);
    CHECK(std::holds_alternative<Plane>(first.primitives[0].shape));
    CHECK(std::get<Plane>(first.primitives[0].shape).normal == Vec3(0.0, 0.0, 2.0));

    // A miss without a crossing point: every measured field stays absent.
    const Expectation& miss = first.primitives[1].expected;
    CHECK_FALSE(miss.hit);
    CHECK_FALSE(miss.near_boundary);
    CHECK(std::isnan(miss.t));
    CHECK(std::isnan(miss.normal.x));
    CHECK(std::isnan(miss.beta));
    CHECK(miss.t_tolerance == 0.0);

    CHECK(std::get<Sphere>(first.primitives[2].shape).radius == 1.0);
    const Expectation& hit = first.primitives[3].expected;
    CHECK(hit.hit);
    CHECK(hit.t == 5.0);
    CHECK(hit.t_tolerance == 1e-12);
    CHECK(hit.normal == Vec3(0.0, 0.0, 1.0));
    CHECK(hit.beta == 0.25);
    CHECK(hit.gamma == 0.5);
    CHECK(hit.barycentric_tolerance == 1e-12);
    CHECK(std::isnan(hit.t_alternative));

    CHECK(axis.cases[2].ray.t_max == 8.0);
    CHECK(axis.cases[4].watertight);
    CHECK(axis.cases[4].primitives[1].expected.near_boundary);
    const Expectation& near_miss = axis.cases[5].primitives[0].expected;
    CHECK(near_miss.near_boundary);
    CHECK_FALSE(near_miss.hit);
    CHECK(near_miss.t == 1.0);
    CHECK(near_miss.beta == 1.0000000000000002);

    const Expectation& on_surface = families[1].cases[3].primitives[0].expected;
    CHECK(on_surface.t == 0.0);
    CHECK(on_surface.t_alternative == 2.0);
    CHECK(on_surface.normal_alternative == Vec3(0.0, 0.0, -1.0));
}

TEST_CASE("write_case_file: every double reads back with the same bits", "[app]") {
    const std::vector<CaseFamily> families = tricky_families();
    const std::string text = written(families);
    CAPTURE(text);
    check_same(families, parse(text));
    // -0 keeps its sign: its text is "-0", not "0".
    CHECK(text.find("ray 0.10000000000000001 -0 1.0000000000000001e+300") != std::string::npos);
}

TEST_CASE("write_case_file: a file read and written again gives the same text", "[app]") {
    const std::vector<CaseFamily> families = read_case_file(kCases / "axis-aligned.cases");
    const std::string text = written(families);
    CAPTURE(text);
    check_same(families, parse(text));
    CHECK(written(parse(text)) == text);
}

TEST_CASE("case_text: shows one case from 'case' to 'end'", "[app]") {
    RayCase ray_case;
    ray_case.index = 3;
    ray_case.watertight = true;
    ray_case.ray = {{0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}, 0.0, kInfinity};
    Expectation hit = measured_hit(5.0, {0.0, 0.0, 1.0});
    hit.t_tolerance = 0.5;
    hit.normal_tolerance = 0.25;
    hit.beta = 0.25;
    hit.gamma = 0.5;
    hit.barycentric_tolerance = 0.125;
    ray_case.primitives.push_back({Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, hit});
    ray_case.primitives.push_back({Sphere{{0, 0, -3}, 1}, Expectation{}});
    CHECK(case_text(ray_case) ==
          "case 3 watertight\n"
          "ray 0 0 5 0 0 -1 0 inf\n"
          "triangle 0 0 0 1 0 0 0 1 0 hit 5 tolerance 0.5 normal 0 0 1 tolerance 0.25 "
          "barycentric 0.25 0.5 tolerance 0.125\n"
          "sphere 0 0 -3 1 miss\n"
          "end\n");
}

TEST_CASE("parse_case_file: ignores comments, blank lines and Windows line ends", "[app]") {
    const std::vector<CaseFamily> families = parse(
        "# a comment\r\n\r\nfamily f seed 3   # trailing comment\r\n"
        "description  two  spaces kept # not this\r\n"
        "case 7\r\nray 0 0 1 0 0 -1 0 inf\r\nplane 0 0 0 0 0 1 hit 1 tolerance 0 normal 0 0 1 "
        "tolerance 0\r\nend\r\n");
    REQUIRE(families.size() == 1);
    CHECK(families[0].description == "two  spaces kept");
    REQUIRE(families[0].cases.size() == 1);
    CHECK(families[0].cases[0].index == 7);
    CHECK(families[0].cases[0].primitives[0].expected.t == 1.0);
}

TEST_CASE("parse_case_file: every malformed line is reported as file:line: problem", "[app]") {
    const std::string family = "family f seed 1\n";
    const std::string ray = "case 0\nray 0 0 1 0 0 -1 0 inf\n";  // lines 2 and 3
    const std::string hit = " hit 1 tolerance 0 normal 0 0 1 tolerance 0";
    const std::vector<BadFile> bad = {
        {"unknown keyword", family + "sphre 0 0 0 1 miss\n",
         "t.cases:2: unknown keyword 'sphre'; did you mean 'sphere'?"},
        {"a far-off unknown keyword", family + "camera 0 0 0\n",
         "t.cases:2: unknown keyword 'camera'"},
        {"family without its seed", "family f 1\n",
         "t.cases:1: 'family' takes NAME seed N, found 2 fields"},
        {"family with another word for seed", "family f sede 1\n",
         "t.cases:1: expected 'seed', found 'sede'"},
        {"a negative seed", "family f seed -1\n", "t.cases:1: the seed '-1' must not be negative"},
        {"a ray short of a number", family + "case 0\nray 0 0 1 0 0 -1 0\n",
         "t.cases:3: 'ray' takes 8 fields (ox oy oz dx dy dz tmin tmax), found 7 fields"},
        {"a bad number", family + "case 0\nray 0 0 1 0 0 -1x 0 inf\n",
         "t.cases:3: the ray's direction '-1x' is not a number"},
        {"inf other than t_max", family + "case 0\nray 0 0 1 0 0 -1 inf inf\n",
         "t.cases:3: t_min 'inf' is not finite"},
        {"nan", family + "case 0\nray 0 0 nan 0 0 -1 0 inf\n",
         "t.cases:3: the ray's origin 'nan' is not finite"},
        {"a second ray", family + ray + "ray 0 0 1 0 0 -1 0 inf\n",
         "t.cases:4: a second 'ray' in case 0, which has one already (line 3)"},
        {"a case without a ray", family + "case 0\nend\n", "t.cases:3: case 0 has no 'ray'"},
        {"a primitive before the ray", family + "case 0\nsphere 0 0 0 1 miss\n",
         "t.cases:3: 'sphere' before the case's 'ray'"},
        {"a case without primitives", family + ray + "end\n",
         "t.cases:4: case 0 has no primitives: give a sphere, triangle or plane"},
        {"a missing end at the end of the file", family + ray + "sphere 0 0 0 1 miss\n",
         "t.cases:2: case 0 has no 'end'"},
        {"a missing end before the next case", family + ray + "sphere 0 0 0 1 miss\ncase 1\n",
         "t.cases:5: 'case' inside case 0 (line 2): its 'end' is missing"},
        {"a missing end before the next family", family + ray + "sphere 0 0 0 1 miss\n" + family,
         "t.cases:5: 'family' inside case 0 (line 2): its 'end' is missing"},
        {"end without case", family + "end\n", "t.cases:2: 'end' without a 'case'"},
        {"end with fields", family + ray + "sphere 0 0 0 1 miss\nend now\n",
         "t.cases:5: 'end' takes nothing, found 1 field"},
        {"a case outside a family", "case 0\n",
         "t.cases:1: 'case' before any 'family': every case belongs to a family"},
        {"a bad word after the case index", family + "case 0 closed\n",
         "t.cases:2: expected 'watertight' or nothing after the case index, found 'closed'"},
        {"a ray outside a case", family + "ray 0 0 1 0 0 -1 0 inf\n",
         "t.cases:2: 'ray' outside a case: it belongs between 'case' and 'end'"},
        {"a primitive outside a case", family + "plane 0 0 0 0 0 1 miss\n",
         "t.cases:2: 'plane' outside a case: it belongs between 'case' and 'end'"},
        {"a description twice", family + "description one\ndescription two\n",
         "t.cases:3: 'description' comes at most once, on the line right after its 'family'"},
        {"a description after a case", family + ray + "sphere 0 0 0 1 miss\nend\ndescription x\n",
         "t.cases:6: 'description' comes at most once, on the line right after its 'family'"},
        {"a primitive short of its numbers", family + ray + "triangle 0 0 0 1 0 0 0 1 hit\n",
         "t.cases:4: 'triangle' takes x0 y0 z0 x1 y1 z1 x2 y2 z2 and then 'hit' or 'miss', "
         "found 9 fields"},
        {"neither hit nor miss", family + ray + "sphere 0 0 0 1 maybe\n",
         "t.cases:4: expected 'hit' or 'miss', found 'maybe'"},
        {"a hit without its t", family + ray + "sphere 0 0 0 1 hit\n",
         "t.cases:4: a hit needs its t and normal: 'hit T tolerance TT normal NX NY NZ tolerance "
         "NT'"},
        {"a triangle hit without its barycentrics",
         family + ray + "triangle 0 0 0 1 0 0 0 1 0" + hit + "\n",
         "t.cases:4: a triangle hit needs its barycentric coordinates: '... barycentric BETA "
         "GAMMA tolerance BT'"},
        {"barycentrics on a sphere",
         family + ray + "sphere 0 0 0 1" + hit + " barycentric 0 0 tolerance 0\n",
         "t.cases:4: 'sphere' with 'barycentric': only a triangle has barycentric coordinates"},
        {"an alternative on a plane",
         family + ray + "plane 0 0 0 0 0 1" + hit + " alternative 2 normal 0 0 1\n",
         "t.cases:4: 'plane' with 'alternative': only a sphere has a second hit that passes"},
        {"a line that stops inside the expectation",
         family + ray + "sphere 0 0 0 1 hit 1 tolerance 0 normal 0 0\n",
         "t.cases:4: the line ends where the normal should be"},
        {"a misspelt word inside the expectation",
         family + ray + "sphere 0 0 0 1 hit 1 tolerence 0 normal 0 0 1 tolerance 0\n",
         "t.cases:4: expected 'tolerance', found 'tolerence'"},
        {"a field after the expectation", family + ray + "sphere 0 0 0 1" + hit + " extra\n",
         "t.cases:4: unexpected 'extra' after the expectation"},
        {"a negative t tolerance",
         family + ray + "plane 0 0 0 0 0 1 hit 1 tolerance -1e-12 normal 0 0 1 tolerance 0\n",
         "t.cases:4: the t tolerance '-1e-12' must not be negative"},
        {"a negative normal tolerance",
         family + ray + "plane 0 0 0 0 0 1 hit 1 tolerance 0 normal 0 0 1 tolerance -1\n",
         "t.cases:4: the normal tolerance '-1' must not be negative"},
        {"a negative barycentric tolerance",
         family + ray + "triangle 0 0 0 1 0 0 0 1 0" + hit + " barycentric 0 0 tolerance -0.5\n",
         "t.cases:4: the barycentric tolerance '-0.5' must not be negative"},
    };
    for (const BadFile& file : bad) {
        CAPTURE(file.why, file.text);
        CHECK_THROWS_WITH(parse(file.text), file.message);
        CHECK_THROWS_AS(parse(file.text), InputError);
    }
}

TEST_CASE("parse_case_file: rejects what would be checked silently wrong, at its line", "[app]") {
    const std::string family = "family f seed 1\n";
    const std::string ray = "case 0\nray 0 0 1 0 0 -1 0 inf\n";       // lines 2 and 3
    const std::string one_case = ray + "sphere 0 0 0 1 miss\nend\n";  // lines 2 to 5
    const std::vector<BadFile> bad = {
        {"a negative radius", family + ray + "sphere 0 0 0 -1 miss\n",
         "t.cases:4: the radius '-1' must not be negative"},
        {"a hit on a sphere of radius 0",
         family + ray + "sphere 0 0 0 0 hit 1 tolerance 0 normal 0 0 1 tolerance 0\n",
         "t.cases:4: a hit on a sphere of radius 0: the contract makes it a miss"},
        {"a hit on a ray without a direction",
         family + "case 0\nray 0 0 1 0 -0 0 0 inf\n" +
             "plane 0 0 0 0 0 1 hit 1 tolerance 0 normal 0 0 1 tolerance 0\n",
         "t.cases:4: a hit on a ray whose direction is zero: the contract makes it a miss"},
        {"a hit on a plane without a normal",
         family + ray + "plane 0 0 0 0 0 0 hit 1 tolerance 0 normal 0 0 1 tolerance 0\n",
         "t.cases:4: a hit on a plane whose normal is zero: the contract makes it a miss"},
        {"an expected normal that is not unit length",
         family + ray + "plane 0 0 0 0 0 1 hit 1 tolerance 0 normal 0 0 2 tolerance 0\n",
         "t.cases:4: the normal (0, 0, 2) is not unit length (its length is 2)"},
        {"an alternative normal that is not unit length",
         family + ray +
             "sphere 0 0 0 1 hit 0 tolerance 0 normal 0 0 1 tolerance 0 alternative 2 normal 0 0 "
             "0\n",
         "t.cases:4: the alternative normal (0, 0, 0) is not unit length (its length is 0)"},
        {"an empty file", "", "t.cases: no 'family' in the file: it has no cases to check"},
        {"a file of comments only", "# nothing yet\n\n",
         "t.cases: no 'family' in the file: it has no cases to check"},
        {"a family without cases at the end", family, "t.cases:1: family 'f' has no cases"},
        {"a family without cases before the next", family + "family g seed 2\n" + one_case,
         "t.cases:1: family 'f' has no cases"},
        {"a case number twice in a family", family + one_case + one_case,
         "t.cases:6: case 0 again in family 'f': the first is on line 2"},
        {"a family name twice", family + one_case + family + one_case,
         "t.cases:6: family 'f' again: the first is on line 1"},
    };
    for (const BadFile& file : bad) {
        CAPTURE(file.why, file.text);
        CHECK_THROWS_WITH(parse(file.text), file.message);
        CHECK_THROWS_AS(parse(file.text), InputError);
    }
}

TEST_CASE("parse_case_file: degenerate input is a case when it expects the contract's miss",
          "[app]") {
    const std::vector<CaseFamily> families = parse(
        "family f seed 1\n"
        "case 0\nray 0 0 1 0 0 -1 0 inf\nsphere 0 0 0 0 miss\nplane 0 0 0 0 0 0 miss\nend\n"
        "case 1\nray 0 0 1 0 0 0 0 inf\nsphere 0 0 0 1 miss\nend\n");
    REQUIRE(families.size() == 1);
    REQUIRE(families[0].cases.size() == 2);
    CHECK(std::get<Sphere>(families[0].cases[0].primitives[0].shape).radius == 0.0);
    CHECK(families[0].cases[1].ray.direction == Vec3(0.0));
}

TEST_CASE("parse_case_file: one case number in two families is two cases", "[app]") {
    const std::string one_case = "case 0\nray 0 0 1 0 0 -1 0 inf\nsphere 0 0 0 1 miss\nend\n";
    const std::vector<CaseFamily> families =
        parse("family f seed 1\n" + one_case + "family g seed 1\n" + one_case);
    REQUIRE(families.size() == 2);
    CHECK(families[1].cases.at(0).index == 0);
}

TEST_CASE("read_case_file: a missing file is reported by its name", "[app]") {
    const std::filesystem::path missing = kCases / "no-such-file.cases";
    CHECK_THROWS_WITH(read_case_file(missing), missing.string() + ": case file not found");
    CHECK_THROWS_WITH(read_case_file(kCases), kCases.string() + ": not a regular file");
}

TEST_CASE("read_case_file: a cut-off file names the case that has no end", "[app]") {
    const std::filesystem::path file = kCases / "bad" / "missing-end.cases";
    CHECK_THROWS_WITH(read_case_file(file), file.string() + ":3: case 0 has no 'end'");
}
