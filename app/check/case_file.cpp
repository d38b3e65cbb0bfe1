#include "app/check/case_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <string_view>
#include <variant>

#include "app/check/case_format.h"
#include "base/errors/input_error.h"
#include "base/scene/text_fields.h"
#include "base/scene/text_file.h"

namespace raystep {

namespace {

constexpr std::string_view kKeywords[] = {"family", "description", "case",  "ray",
                                          "sphere", "triangle",    "plane", "end"};

// How far from 1 an expected normal's length may be: what case scoring allows a reported one.
constexpr double kUnitNormalSlack = 1e-9;

// The expectation's optional part, as error messages quote it.
constexpr const char* kMeasuredPart = "T tolerance TT normal NX NY NZ tolerance NT";
constexpr const char* kBarycentricPart = "barycentric BETA GAMMA tolerance BT";

// Reads a case file line by line. A case is open from its `case` line to its `end` line; every
// problem is reported at the line that shows it.
class CaseFileParser {
  public:
    explicit CaseFileParser(std::string name) : name_(std::move(name)) {}

    void parse_line(const std::string& text) {
        ++line_;
        split_fields(text, fields_);
        if (fields_.empty()) return;
        next_ = 1;

        const std::string_view keyword = fields_[0];
        if (keyword == "family") {
            family();
        } else if (keyword == "description") {
            description();
        } else if (keyword == "case") {
            begin_case();
        } else if (keyword == "ray") {
            ray();
        } else if (keyword == "sphere" || keyword == "triangle" || keyword == "plane") {
            primitive(keyword);
        } else if (keyword == "end") {
            end_case();
        } else {
            unknown(keyword);
        }
        description_allowed_ = keyword == "family";
    }

    std::vector<CaseFamily> finish() {
        if (open_case_) {
            throw InputError(name_, case_line_, open_case_name() + " has no 'end'");
        }
        // No line is to blame for a file without families: it names the file alone.
        if (families_.empty()) {
            throw InputError(name_, 0, "no 'family' in the file: it has no cases to check");
        }
        require_cases_in_last_family();
        return std::move(families_);
    }

  private:
    [[noreturn]] void fail(const std::string& problem) const {
        throw InputError(name_, line_, problem);
    }

    std::string keyword() const { return "'" + std::string(fields_[0]) + "'"; }

    // Lines of a fixed length: `usage` names their fields.
    void expect_fields(std::size_t count, const std::string& usage) const {
        const std::size_t given = fields_.size() - 1;
        if (given != count) {
            fail(keyword() + " takes " + usage + ", found " + std::to_string(given) + " field" +
                 (given == 1 ? "" : "s"));
        }
    }

    // Fields in order, for the lines whose length varies.

    bool at(std::string_view word) const {
        return next_ < fields_.size() && fields_[next_] == word;
    }

    std::string_view take(const std::string& what) {
        if (next_ == fields_.size()) fail("the line ends where " + what + " should be");
        return fields_[next_++];
    }

    void word(std::string_view expected) {
        const std::string quoted = "'" + std::string(expected) + "'";
        const std::string_view found = take(quoted);
        if (found != expected) fail("expected " + quoted + ", found " + quoted_field(found));
    }

    double number(const std::string& what) {
        return parse_finite_number(take(what), {name_, line_}, what);
    }

    Vec3 vec3(const std::string& what) {
        const double x = number(what);
        const double y = number(what);
        return {x, y, number(what)};
    }

    // An expected normal is unit length within the 1e-9 that scoring asks of a reported one
    // (docs/case-files.md): any other length is a normal no correct method can match.
    Vec3 unit_normal(const std::string& what) {
        const Vec3 normal = vec3(what);
        const double length =
            std::sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
        if (!(std::abs(length - 1.0) <= kUnitNormalSlack)) {
            fail(what + " " + exact_text(normal) + " is not unit length (its length is " +
                 exact_text(length) + ")");
        }
        return normal;
    }

    double tolerance(const std::string& what) {
        const std::string_view token = take(what);
        const double value = parse_finite_number(token, {name_, line_}, what);
        if (value < 0.0) fail(what + " " + quoted_field(token) + " must not be negative");
        return value;
    }

    std::string open_case_name() const { return "case " + std::to_string(open_case_->index); }

    // A family without cases checks nothing, though its name would be listed as checked.
    void require_cases_in_last_family() const {
        if (!families_.empty() && families_.back().cases.empty()) {
            throw InputError(name_, family_line_,
                             "family '" + families_.back().name + "' has no cases");
        }
    }

    void require_no_open_case() const {
        if (open_case_) {
            fail(keyword() + " inside " + open_case_name() + " (line " +
                 std::to_string(case_line_) + "): its 'end' is missing");
        }
    }

    void require_open_case() const {
        if (!open_case_) fail(keyword() + " outside a case: it belongs between 'case' and 'end'");
    }

    // Keywords

    void family() {
        require_no_open_case();
        expect_fields(3, "NAME seed N");
        CaseFamily family;
        family.name = std::string(fields_[1]);
        next_ = 2;
        word("seed");
        family.seed =
            static_cast<std::uint64_t>(parse_count(fields_[3], {name_, line_}, "the seed"));
        // A name picks a family (--family) and labels its results: two of one name would be
        // checked and reported as one.
        const auto [first, added] = family_lines_.emplace(family.name, line_);
        if (!added) {
            fail("family '" + family.name + "' again: the first is on line " +
                 std::to_string(first->second));
        }
        require_cases_in_last_family();
        families_.push_back(std::move(family));
        family_line_ = line_;
        case_lines_.clear();
    }

    void description() {
        if (!description_allowed_) {
            fail("'description' comes at most once, on the line right after its 'family'");
        }
        if (fields_.size() < 2) fail("'description' takes the text that describes the family");
        // The rest of the line as written, comment and surrounding white space dropped.
        const std::string_view& last = fields_.back();
        families_.back().description.assign(fields_[1].data(),
                                            last.data() + last.size() - fields_[1].data());
    }

    void begin_case() {
        if (families_.empty()) fail("'case' before any 'family': every case belongs to a family");
        require_no_open_case();
        if (fields_.size() != 2 && fields_.size() != 3) {
            fail("'case' takes INDEX and then optionally 'watertight', found " +
                 std::to_string(fields_.size() - 1) + " fields");
        }
        RayCase ray_case;
        ray_case.index =
            static_cast<std::uint64_t>(parse_count(fields_[1], {name_, line_}, "the case index"));
        // An index picks a case (--case) and names it in a counterexample: it must name one.
        const auto [first, added] = case_lines_.emplace(ray_case.index, line_);
        if (!added) {
            fail("case " + std::to_string(ray_case.index) + " again in family '" +
                 families_.back().name + "': the first is on line " +
                 std::to_string(first->second));
        }
        if (fields_.size() == 3) {
            if (fields_[2] != "watertight") {
                fail("expected 'watertight' or nothing after the case index, found " +
                     quoted_field(fields_[2]));
            }
            ray_case.watertight = true;
        }
        open_case_ = std::move(ray_case);
        case_line_ = line_;
        ray_line_ = 0;
    }

    void ray() {
        require_open_case();
        if (ray_line_ != 0) {
            fail("a second 'ray' in " + open_case_name() + ", which has one already (line " +
                 std::to_string(ray_line_) + ")");
        }
        expect_fields(8, "8 fields (ox oy oz dx dy dz tmin tmax)");
        Ray& ray = open_case_->ray;
        ray.origin = vec3("the ray's origin");
        ray.direction = vec3("the ray's direction");
        ray.t_min = number("t_min");
        // An unbounded ray is the common case, so t_max alone may be infinite.
        if (fields_[8] == "inf") {
            ray.t_max = std::numeric_limits<double>::infinity();
        } else {
            ray.t_max = number("t_max");
        }
        ray_line_ = line_;
    }

    void primitive(std::string_view kind) {
        require_open_case();
        if (ray_line_ == 0) fail(keyword() + " before the case's 'ray'");

        std::size_t numbers = 0;
        std::string usage;
        if (kind == "sphere") {
            numbers = 4;
            usage = "cx cy cz r";
        } else if (kind == "triangle") {
            numbers = 9;
            usage = "x0 y0 z0 x1 y1 z1 x2 y2 z2";
        } else {
            numbers = 6;
            usage = "px py pz nx ny nz";
        }
        if (fields_.size() < 1 + numbers + 1) {
            fail(keyword() + " takes " + usage + " and then 'hit' or 'miss', found " +
                 std::to_string(fields_.size() - 1) + " fields");
        }

        CaseShape shape;
        if (kind == "sphere") {
            const Vec3 center = vec3("the centre");
            const std::string_view radius_field = fields_[next_];
            const double radius = number("the radius");
            if (!(radius >= 0.0)) {
                fail("the radius " + quoted_field(radius_field) + " must not be negative");
            }
            shape = Sphere{center, radius};
        } else if (kind == "triangle") {
            const Vec3 p0 = vec3("a vertex");
            const Vec3 p1 = vec3("a vertex");
            shape = Triangle{p0, p1, vec3("a vertex")};
        } else {
            const Vec3 point = vec3("the plane's point");
            const Vec3 normal = vec3("the plane's normal");
            shape = Plane{point, normal};
        }
        const Expectation expected = expectation(shape);
        // The contract makes degenerate input a miss (stages/3_intersect/intersect.h), so a case
        // may hold it, but only as one.
        if (expected.hit) {
            if (open_case_->ray.direction == Vec3(0.0)) {
                fail("a hit on a ray whose direction is zero: the contract makes it a miss");
            }
            if (const Sphere* sphere = std::get_if<Sphere>(&shape);
                sphere && sphere->radius == 0.0) {
                fail("a hit on a sphere of radius 0: the contract makes it a miss");
            }
            if (const Plane* plane = std::get_if<Plane>(&shape);
                plane && plane->normal == Vec3(0.0)) {
                fail("a hit on a plane whose normal is zero: the contract makes it a miss");
            }
        }
        open_case_->primitives.push_back({shape, expected});
    }

    // `[near-boundary] hit|miss`, then the measured part, then a sphere's alternative or a
    // triangle's barycentrics.
    Expectation expectation(const CaseShape& shape) {
        const bool is_triangle = std::holds_alternative<Triangle>(shape);
        Expectation e;
        std::string_view decision = take("'hit' or 'miss'");
        if (decision == "near-boundary") {
            e.near_boundary = true;
            decision = take("'hit' or 'miss'");
        }
        if (decision != "hit" && decision != "miss") {
            fail("expected 'hit' or 'miss', found " + quoted_field(decision));
        }
        e.hit = decision == "hit";

        if (next_ == fields_.size()) {
            if (e.hit) {
                fail(std::string("a hit needs its t and normal: 'hit ") + kMeasuredPart +
                     (is_triangle ? std::string(" ") + kBarycentricPart : "") + "'");
            }
            return e;
        }

        e.t = number("t");
        word("tolerance");
        e.t_tolerance = tolerance("the t tolerance");
        word("normal");
        e.normal = unit_normal("the normal");
        word("tolerance");
        e.normal_tolerance = tolerance("the normal tolerance");

        if (at("alternative")) {
            if (!std::holds_alternative<Sphere>(shape)) {
                fail(keyword() + " with 'alternative': only a sphere has a second hit that passes");
            }
            ++next_;
            e.t_alternative = number("the alternative t");
            word("normal");
            e.normal_alternative = unit_normal("the alternative normal");
        }
        if (at("barycentric")) {
            if (!is_triangle) {
                fail(keyword() +
                     " with 'barycentric': only a triangle has barycentric coordinates");
            }
            ++next_;
            e.beta = number("beta");
            e.gamma = number("gamma");
            word("tolerance");
            e.barycentric_tolerance = tolerance("the barycentric tolerance");
        } else if (is_triangle && e.hit) {
            fail(std::string("a triangle hit needs its barycentric coordinates: '... ") +
                 kBarycentricPart + "'");
        }
        if (next_ != fields_.size()) {
            fail("unexpected " + quoted_field(fields_[next_]) + " after the expectation");
        }
        return e;
    }

    void end_case() {
        if (!open_case_) fail("'end' without a 'case'");
        expect_fields(0, "nothing");
        if (ray_line_ == 0) fail(open_case_name() + " has no 'ray'");
        if (open_case_->primitives.empty()) {
            fail(open_case_name() + " has no primitives: give a sphere, triangle or plane");
        }
        families_.back().cases.push_back(std::move(*open_case_));
        open_case_.reset();
    }

    void unknown(std::string_view found) const {
        std::string message = "unknown keyword " + quoted_field(found);
        // A typo is a few characters off a keyword; a longer word is not worth measuring.
        if (found.size() <= 20) {
            const auto nearest =
                std::min_element(std::begin(kKeywords), std::end(kKeywords),
                                 [&](std::string_view a, std::string_view b) {
                                     return edit_distance(found, a) < edit_distance(found, b);
                                 });
            if (edit_distance(found, *nearest) <= 2) {
                message += "; did you mean '" + std::string(*nearest) + "'?";
            }
        }
        fail(message);
    }

    std::string name_;
    int line_ = 0;
    std::vector<std::string_view> fields_;
    std::size_t next_ = 1;  // the next field to read on this line
    std::vector<CaseFamily> families_;
    bool description_allowed_ = false;  // the previous line was `family`
    std::optional<RayCase> open_case_;
    int family_line_ = 0;                      // the last family's line
    std::map<std::string, int> family_lines_;  // every family's line, by name
    std::map<std::uint64_t, int> case_lines_;  // the last family's cases' lines
    int case_line_ = 0;
    int ray_line_ = 0;  // 0 until the open case has its ray
};

void write_vec3(std::ostream& out, const Vec3& v) {
    out << ' ' << exact_text(v.x) << ' ' << exact_text(v.y) << ' ' << exact_text(v.z);
}

// The parts a reader would reject are left out: an alternative off a sphere, barycentrics off a
// triangle.
void write_expectation(std::ostream& out, const CaseShape& shape, const Expectation& e) {
    if (e.near_boundary) out << " near-boundary";
    out << (e.hit ? " hit" : " miss");
    if (std::isnan(e.t)) return;
    out << ' ' << exact_text(e.t) << " tolerance " << exact_text(e.t_tolerance) << " normal";
    write_vec3(out, e.normal);
    out << " tolerance " << exact_text(e.normal_tolerance);
    if (std::holds_alternative<Sphere>(shape) && !std::isnan(e.t_alternative)) {
        out << " alternative " << exact_text(e.t_alternative) << " normal";
        write_vec3(out, e.normal_alternative);
    }
    if (std::holds_alternative<Triangle>(shape) && !std::isnan(e.beta)) {
        out << " barycentric " << exact_text(e.beta) << ' ' << exact_text(e.gamma) << " tolerance "
            << exact_text(e.barycentric_tolerance);
    }
}

void write_primitive(std::ostream& out, const CasePrimitive& primitive) {
    out << shape_name(primitive.shape);
    if (const auto* sphere = std::get_if<Sphere>(&primitive.shape)) {
        write_vec3(out, sphere->center);
        out << ' ' << exact_text(sphere->radius);
    } else if (const auto* triangle = std::get_if<Triangle>(&primitive.shape)) {
        write_vec3(out, triangle->p0);
        write_vec3(out, triangle->p1);
        write_vec3(out, triangle->p2);
    } else if (const auto* plane = std::get_if<Plane>(&primitive.shape)) {
        write_vec3(out, plane->point);
        write_vec3(out, plane->normal);
    }
    write_expectation(out, primitive.shape, primitive.expected);
    out << '\n';
}

}  // namespace

std::vector<std::filesystem::path> case_files_in(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.is_regular_file() && entry.path().extension() == ".cases") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<CaseFamily> read_case_file(const std::filesystem::path& path) {
    return parse_case_file(read_text_file(path, "case file"), path.string());
}

std::vector<CaseFamily> parse_case_file(const std::string& text, const std::string& name) {
    CaseFileParser parser(name);
    std::istringstream in(text);
    // A std::string per line ends each field with a space or NUL, where strtod stops.
    for (std::string line; std::getline(in, line);)
        parser.parse_line(line);
    return parser.finish();
}

void write_case_file(std::ostream& out, const std::vector<CaseFamily>& families) {
    out << "# raystep ray cases (docs/case-files.md)\n";
    for (const CaseFamily& family : families) {
        out << "family " << family.name << " seed " << family.seed << '\n';
        if (!family.description.empty()) out << "description " << family.description << '\n';
        for (const RayCase& ray_case : family.cases)
            out << case_text(ray_case);
    }
}

std::string case_text(const RayCase& ray_case) {
    std::ostringstream out;
    out << "case " << ray_case.index << (ray_case.watertight ? " watertight" : "") << '\n';
    out << "ray";
    write_vec3(out, ray_case.ray.origin);
    write_vec3(out, ray_case.ray.direction);
    out << ' ' << exact_text(ray_case.ray.t_min) << ' ' << exact_text(ray_case.ray.t_max) << '\n';
    for (const CasePrimitive& primitive : ray_case.primitives)
        write_primitive(out, primitive);
    out << "end\n";
    return out.str();
}

}  // namespace raystep
