#include "base/scene/scene_loader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>

#include "base/errors/input_error.h"
#include "base/math/parallel_sine.h"
#include "base/math/to_text.h"
#include "base/scene/mesh_loader.h"
#include "base/scene/text_fields.h"
#include "base/scene/text_file.h"

namespace raystep {

namespace {

// Limits that keep a typo from exhausting memory or the stack; each is far above any real
// scene and each is reported as an error, never clamped.
constexpr long kMaxImageSide = 32768;
constexpr long kMaxImagePixels = 1L << 27;  // 128 Mpixels, 1.5 GiB of float RGB
constexpr long kMaxDepth = 1000;
// `spp` and `lightsamples`: each sample is at least a ray per pixel or per light and pixel, so
// 2^16 of them at 640 x 480 is already 2 x 10^10 rays.
constexpr long kMaxSamples = 1L << 16;

// A direction (an up vector, a normal, an axis, a scale factor) must have its largest component
// in this range: then |v|^2 neither overflows nor underflows, and normalizing or inverting it is
// safe in anyone's code.
constexpr double kSmallestDirection = 1e-150;
constexpr double kLargestDirection = 1e150;

// Every number in a scene: the range in which products of three coordinates still fit in a
// double, the domain of the stage-3 contract.
constexpr double kLargestNumber = 1e100;

constexpr std::uint32_t kUnregistered = std::numeric_limits<std::uint32_t>::max();

double largest_magnitude(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Translate by 0, scale by 1 and rotate by 0 degrees change nothing, so an object under only
// such ops needs no matrix at all.
bool is_identity(const TransformOp& op) {
    switch (op.kind) {
        case TransformOp::Kind::translate:
            return op.vector == Vec3(0.0);
        case TransformOp::Kind::scale:
            return op.vector == Vec3(1.0);
        case TransformOp::Kind::rotate:
            return op.angle_degrees == 0.0;
    }
    return false;
}

class SceneParser {
  public:
    SceneParser(std::string name, std::filesystem::path folder)
        : name_(std::move(name)), folder_(std::move(folder)) {
        scene_.path = name_;
    }

    void parse_line(std::string_view text) {
        ++line_;
        split_fields(text, fields_);
        if (fields_.empty()) return;

        const Command& command = find_command(fields_[0]);
        const std::size_t given = fields_.size() - 1;
        if (given < command.argument_count ||
            given > command.argument_count + command.optional_count) {
            const std::string count =
                command.optional_count == 0
                    ? std::to_string(command.argument_count)
                    : std::to_string(command.argument_count) + " or " +
                          std::to_string(command.argument_count + command.optional_count);
            fail("'" + std::string(command.name) + "' takes " + count + " argument" +
                 (count == "1" ? "" : "s") +
                 (command.arguments.empty() ? "" : " (" + std::string(command.arguments) + ")") +
                 ", found " + std::to_string(given));
        }
        (this->*command.handle)();
    }

    Scene finish() {
        if (line_of("camera") == 0) {
            throw InputError(name_, 0, "the scene has no 'camera' command, so nothing can be seen");
        }
        scene_.camera.ortho = ortho_;
        check_sample_grids();
        std::stable_sort(scene_.notes.begin(), scene_.notes.end(),
                         [](const SceneNote& a, const SceneNote& b) { return a.line < b.line; });
        return std::move(scene_);
    }

  private:
    struct Command {
        std::string_view name;
        std::string_view arguments;  // names of the arguments, separated by spaces; [optional]
        void (SceneParser::*handle)();
        std::size_t argument_count = 0;
        std::size_t optional_count = 0;

        Command(std::string_view command, std::string_view argument_names,
                void (SceneParser::*handler)())
            : name(command), arguments(argument_names), handle(handler) {
            std::vector<std::string_view> names;
            split_fields(arguments, names);
            for (const std::string_view argument : names) {
                ++(argument.front() == '[' ? optional_count : argument_count);
            }
        }
    };

    static const std::vector<Command>& commands() {
        static const std::vector<Command> table = {
            {"size", "width height", &SceneParser::size},
            {"maxdepth", "depth", &SceneParser::maxdepth},
            {"output", "filename", &SceneParser::output},
            {"camera", "fromx fromy fromz atx aty atz upx upy upz fovy", &SceneParser::camera},
            {"ortho", "left right bottom top", &SceneParser::ortho},
            {"rayoffset", "rule [epsilon]", &SceneParser::rayoffset},
            {"sphere", "x y z radius", &SceneParser::sphere},
            {"plane", "x y z nx ny nz", &SceneParser::plane},
            {"maxverts", "count", &SceneParser::maxverts},
            {"maxvertnorms", "count", &SceneParser::maxvertnorms},
            {"vertex", "x y z", &SceneParser::vertex},
            {"vertexnormal", "x y z nx ny nz", &SceneParser::vertexnormal},
            {"tri", "v0 v1 v2", &SceneParser::tri},
            {"trinormal", "v0 v1 v2", &SceneParser::trinormal},
            {"mesh", "file", &SceneParser::mesh},
            {"define", "name file", &SceneParser::define},
            {"instance", "name", &SceneParser::instance},
            {"translate", "x y z", &SceneParser::translate},
            {"rotate", "axisx axisy axisz degrees", &SceneParser::rotate},
            {"scale", "x y z", &SceneParser::scale},
            {"pushTransform", "", &SceneParser::push_transform},
            {"popTransform", "", &SceneParser::pop_transform},
            {"directional", "x y z r g b", &SceneParser::directional},
            {"point", "x y z r g b", &SceneParser::point},
            {"spot", "x y z dx dy dz cutoff exponent r g b", &SceneParser::spot},
            {"quadLight", "ax ay az abx aby abz acx acy acz r g b", &SceneParser::quad_light},
            {"attenuation", "constant linear quadratic", &SceneParser::attenuation},
            {"background", "r g b", &SceneParser::background},
            {"ambient", "r g b", &SceneParser::ambient},
            {"diffuse", "r g b", &SceneParser::diffuse},
            {"specular", "r g b", &SceneParser::specular},
            {"shininess", "s", &SceneParser::shininess},
            {"emission", "r g b", &SceneParser::emission},
            {"transmission", "r g b", &SceneParser::transmission},
            {"ior", "index", &SceneParser::ior},
            {"fresnel", "exact|schlick", &SceneParser::fresnel},
            {"spp", "count", &SceneParser::spp},
            {"pixelsampling", "jittered|regular|random", &SceneParser::pixelsampling},
            {"lightsamples", "count", &SceneParser::lightsamples},
            {"lightstratify", "on|off", &SceneParser::lightstratify},
            {"seed", "number", &SceneParser::seed},
            {"integrator", "raytracer|direct|analyticdirect|pathtracer", &SceneParser::integrator},
            {"nexteventestimation", "on|off|mis", &SceneParser::nexteventestimation},
            {"russianroulette", "on|off", &SceneParser::russianroulette},
            {"importancesampling", "hemisphere|cosine|brdf", &SceneParser::importancesampling},
            {"brdf", "phong|ggx", &SceneParser::brdf},
            {"roughness", "alpha", &SceneParser::roughness},
            {"gamma", "gamma", &SceneParser::gamma},
        };
        return table;
    }

    const Command& find_command(std::string_view name) const {
        const std::vector<Command>& table = commands();
        const auto found = std::find_if(table.begin(), table.end(),
                                        [&](const Command& c) { return c.name == name; });
        if (found != table.end()) return *found;

        std::string message = "unknown command " + quoted_field(name);
        // A typo is a few characters off a command; a longer word is not worth measuring.
        if (name.size() <= 20) {
            const auto nearest = std::min_element(
                table.begin(), table.end(), [&](const Command& a, const Command& b) {
                    return edit_distance(name, a.name) < edit_distance(name, b.name);
                });
            if (edit_distance(name, nearest->name) <= 2) {
                message += "; did you mean '" + std::string(nearest->name) + "'?";
            }
        }
        fail(message);
    }

    // Arguments

    [[noreturn]] void fail(const std::string& problem) const {
        throw InputError(name_, line_, problem);
    }

    double number(std::size_t k, std::string_view what) const {
        const double value = parse_finite_number(fields_[k], {name_, line_}, what);
        if (std::abs(value) > kLargestNumber) {
            fail(std::string(what) + " " + quoted_field(fields_[k]) +
                 " is beyond 1e100, the range in which the renderer computes reliably");
        }
        return value;
    }

    long count(std::size_t k, std::string_view what) const {
        return parse_count(fields_[k], {name_, line_}, what);
    }

    Vec3 vec3(std::size_t first, std::string_view what) const {
        return {number(first, what), number(first + 1, what), number(first + 2, what)};
    }

    // A vector used for its direction only.
    Vec3 direction(std::size_t first, std::string_view what) const {
        const Vec3 v = vec3(first, "a component of " + std::string(what));
        const double m = largest_magnitude(v);
        if (m == 0.0) fail(std::string(what) + " is zero");
        if (m < kSmallestDirection || m > kLargestDirection) {
            fail(std::string(what) + " " + to_text(v) +
                 " is too short or too long to normalize reliably; scale it towards 1");
        }
        return v;
    }

    Color color(std::size_t first) const {
        const Color c = vec3(first, "a colour component");
        if (c.r < 0 || c.g < 0 || c.b < 0) {
            fail("colour " + to_text(c) + " has a negative component");
        }
        return c;
    }

    // The value of field k, one of the words of `choices` ("on|off"): its position among them.
    std::size_t keyword(std::size_t k, std::string_view choices) const {
        std::vector<std::string_view> words;
        std::size_t start = 0;
        while (start <= choices.size()) {
            const std::size_t bar = std::min(choices.find('|', start), choices.size());
            words.push_back(choices.substr(start, bar - start));
            start = bar + 1;
        }
        const auto found = std::find(words.begin(), words.end(), fields_[k]);
        if (found != words.end()) return static_cast<std::size_t>(found - words.begin());
        std::string listed;
        for (std::size_t w = 0; w < words.size(); ++w) {
            listed += (w == 0 ? "" : w + 1 == words.size() ? " or " : ", ") + std::string(words[w]);
        }
        fail("'" + std::string(fields_[0]) + "' takes " + listed + ", not " +
             quoted_field(fields_[k]));
    }

    // A scene-wide setting (`size`, `camera`, `spp`, ...) is given at most once: a second one is
    // an error, never a silent override.
    void once() {
        const auto [first, inserted] =
            first_lines_.try_emplace(std::string(fields_[0]), static_cast<std::uint32_t>(line_));
        if (!inserted) {
            fail("'" + std::string(fields_[0]) + "' was already given on line " +
                 std::to_string(first->second));
        }
    }

    // The line of a once-only command, 0 when the file has none.
    std::uint32_t line_of(const std::string& command) const {
        const auto found = first_lines_.find(command);
        return found == first_lines_.end() ? 0 : found->second;
    }

    // A note on this line for `scene_.notes`; a command that recurs (`brdf` in every material)
    // is noted on its first line only.
    void note(const std::string& text) {
        for (const SceneNote& noted : scene_.notes) {
            if (noted.command == fields_[0]) return;
        }
        scene_.notes.push_back({static_cast<std::uint32_t>(line_), std::string(fields_[0]), text});
    }

    // Image and camera

    void size() {
        once();
        const long width = count(1, "the width");
        const long height = count(2, "the height");
        if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
            fail("image size " + std::to_string(width) + " x " + std::to_string(height) +
                 " is out of range: each side must be 1 to " + std::to_string(kMaxImageSide));
        }
        if (width * height > kMaxImagePixels) {
            fail("image size " + std::to_string(width) + " x " + std::to_string(height) +
                 " has more than " + std::to_string(kMaxImagePixels) + " pixels");
        }
        scene_.width = static_cast<int>(width);
        scene_.height = static_cast<int>(height);
    }

    void maxdepth() {
        once();
        const long depth = count(1, "the depth");
        if (depth > kMaxDepth) {
            fail("maxdepth " + std::to_string(depth) + " is above the limit of " +
                 std::to_string(kMaxDepth));
        }
        scene_.max_depth = static_cast<int>(depth);
    }

    void output() {
        once();
        scene_.output = std::string(fields_[1]);
    }

    void rayoffset() {
        once();
        const std::optional<OffsetRule> rule = parse_offset_rule(fields_[1]);
        if (!rule) {
            fail("unknown ray offset rule " + quoted_field(fields_[1]) +
                 "; the rules are along-ray, along-normal and error-bound");
        }
        scene_.ray_offset.rule = *rule;
        if (!uses_epsilon(*rule)) {
            if (fields_.size() > 2) fail("error-bound takes no epsilon: it needs no tuning");
            return;
        }
        if (fields_.size() < 3) {
            fail(std::string(offset_rule_name(*rule)) + " needs an epsilon, the offset distance");
        }
        const double epsilon = number(2, "epsilon");
        if (!(epsilon > 0.0)) fail("epsilon " + quoted_field(fields_[2]) + " must be positive");
        scene_.ray_offset.epsilon = epsilon;
    }

    void camera() {
        once();
        CameraSpec& c = scene_.camera;
        c.lookfrom = vec3(1, "lookfrom");
        c.lookat = vec3(4, "lookat");
        c.up = direction(7, "the up vector");
        c.fovy_degrees = number(10, "fovy");
        c.line = static_cast<std::uint32_t>(line_);

        // The field of view: tan(fovy / 2) must be positive and finite.
        if (!(c.fovy_degrees > 0.0 && c.fovy_degrees < 180.0)) {
            fail("fovy " + std::string(fields_[10]) +
                 " is out of range: the field of view must be strictly between 0 and 180 degrees");
        }
        // The view direction must exist and span a plane with the up hint. (Every number is at
        // most 1e100, so the difference is finite.)
        const Vec3 view = c.lookat - c.lookfrom;
        const double view_size = largest_magnitude(view);
        if (view_size == 0.0) {
            fail("lookfrom and lookat are the same point " + to_text(c.lookfrom) +
                 ", so there is no view direction");
        }
        // Both scaled by their largest component, so that the products cannot overflow; written
        // so that a NaN counts as parallel.
        const Vec3 a = view / view_size;
        const Vec3 b = c.up / largest_magnitude(c.up);
        if (!(glm::length(glm::cross(a, b)) > kParallelSine * glm::length(a) * glm::length(b))) {
            fail("the up vector " + to_text(c.up) + " is parallel to the view direction " +
                 to_text(view) + ", so the camera cannot tell up from down; choose another up");
        }
    }

    void ortho() {
        once();
        const OrthoWindow window{number(1, "left"), number(2, "right"), number(3, "bottom"),
                                 number(4, "top")};
        if (!(window.left < window.right) || !(window.bottom < window.top)) {
            fail("ortho window must have left < right and bottom < top");
        }
        ortho_ = window;
    }

    // Geometry

    ObjectAttributes attributes() {
        if (material_id_ == kUnregistered) {
            scene_.materials.push_back(material_);
            material_id_ = static_cast<std::uint32_t>(scene_.materials.size() - 1);
        }
        const std::uint32_t node = transform_stack_.back();
        const std::uint32_t transform = scene_.transforms[node].identity ? 0 : node;
        return {material_id_, transform, static_cast<std::uint32_t>(line_)};
    }

    void sphere() {
        const Vec3 center = vec3(1, "the centre");
        const double radius = number(4, "the radius");
        if (!(radius > 0.0)) fail("radius " + std::string(fields_[4]) + " must be positive");
        scene_.spheres.push_back({{center, radius}, attributes()});
    }

    void plane() {
        const Vec3 point = vec3(1, "the point");
        const Vec3 normal = direction(4, "the plane's normal");
        scene_.planes.push_back({{point, normal}, attributes()});
    }

    // maxverts and maxvertnorms are promises, checked as the vertices come; never capacities to
    // allocate, so that a typo cannot reserve gigabytes.
    void maxverts() {
        max_vertices_ = count(1, "the vertex count");
        if (static_cast<std::size_t>(max_vertices_) < vertices_.size()) {
            fail("maxverts " + std::to_string(max_vertices_) + " is less than the " +
                 std::to_string(vertices_.size()) + " vertices already given");
        }
    }

    void maxvertnorms() {
        max_normal_vertices_ = count(1, "the vertex count");
        if (static_cast<std::size_t>(max_normal_vertices_) < normal_vertices_.size()) {
            fail("maxvertnorms " + std::to_string(max_normal_vertices_) + " is less than the " +
                 std::to_string(normal_vertices_.size()) + " vertexnormals already given");
        }
    }

    void vertex() {
        if (max_vertices_ >= 0 && vertices_.size() == static_cast<std::size_t>(max_vertices_)) {
            fail("more vertices than 'maxverts " + std::to_string(max_vertices_) + "' declared");
        }
        vertices_.push_back(vec3(1, "a coordinate"));
    }

    void vertexnormal() {
        if (max_normal_vertices_ >= 0 &&
            normal_vertices_.size() == static_cast<std::size_t>(max_normal_vertices_)) {
            fail("more vertexnormals than 'maxvertnorms " + std::to_string(max_normal_vertices_) +
                 "' declared");
        }
        const Vec3 position = vec3(1, "a coordinate");
        const Vec3 normal = direction(4, "the vertex normal");
        normal_vertices_.push_back({position, normal});
    }

    std::array<std::size_t, 3> indices(std::size_t available, std::string_view pile) const {
        std::array<std::size_t, 3> result{};
        for (std::size_t k = 0; k < 3; ++k) {
            const long index = count(k + 1, "a vertex index");
            if (static_cast<std::size_t>(index) >= available) {
                fail("vertex index " + std::to_string(index) +
                     " is out of range: " + std::to_string(available) + " " + std::string(pile) +
                     " defined so far, numbered from 0");
            }
            result[k] = static_cast<std::size_t>(index);
        }
        return result;
    }

    void tri() {
        const auto [i0, i1, i2] = indices(vertices_.size(), "vertices");
        SceneTriangle triangle;
        triangle.shape = {vertices_[i0], vertices_[i1], vertices_[i2]};
        triangle.attributes = attributes();
        scene_.triangles.push_back(triangle);
    }

    void trinormal() {
        const auto [i0, i1, i2] = indices(normal_vertices_.size(), "vertexnormals");
        SceneTriangle triangle;
        triangle.shape = {normal_vertices_[i0].first, normal_vertices_[i1].first,
                          normal_vertices_[i2].first};
        triangle.attributes = attributes();
        triangle.vertex_normals = static_cast<std::int32_t>(scene_.vertex_normals.size());
        scene_.vertex_normals.push_back({normal_vertices_[i0].second, normal_vertices_[i1].second,
                                         normal_vertices_[i2].second});
        scene_.triangles.push_back(triangle);
    }

    // The mesh file named by field k, resolved against the scene's folder; its errors become
    // this line's.
    std::pair<std::filesystem::path, TriangleMesh> mesh_file(std::size_t k) const {
        std::filesystem::path file{std::string(fields_[k])};
        if (file.is_relative()) file = folder_ / file;
        std::error_code error;
        if (!std::filesystem::exists(file, error)) {
            fail("mesh file " + quoted_field(fields_[k]) + " not found (looked for " +
                 quoted_field(file.string()) + ")");
        }
        TriangleMesh loaded;
        try {
            loaded = load_mesh(file);
        } catch (const InputError& mesh_error) {
            fail(std::string("in mesh: ") + mesh_error.what());
        }
        // The scene's own domain holds for the mesh's coordinates too.
        for (std::size_t v = 0; v < loaded.positions.size(); ++v) {
            if (largest_magnitude(loaded.positions[v]) > kLargestNumber) {
                fail("in mesh " + quoted_field(fields_[k]) + ": vertex " + std::to_string(v) + " " +
                     to_text(loaded.positions[v]) +
                     " has a coordinate beyond 1e100, the range in which the renderer computes "
                     "reliably");
            }
        }
        return {file, std::move(loaded)};
    }

    void mesh() {
        const auto [file, loaded] = mesh_file(1);

        SceneMesh record;
        record.path = file.string();
        record.first_triangle = static_cast<std::uint32_t>(scene_.triangles.size());
        record.triangle_count = static_cast<std::uint32_t>(loaded.faces.size());
        record.line = static_cast<std::uint32_t>(line_);
        const auto mesh_id = static_cast<std::int32_t>(scene_.meshes.size());
        scene_.meshes.push_back(record);

        const ObjectAttributes shared = attributes();
        scene_.triangles.reserve(scene_.triangles.size() + loaded.faces.size());
        for (const auto& face : loaded.faces) {
            SceneTriangle triangle;
            triangle.shape = {loaded.positions[face[0]], loaded.positions[face[1]],
                              loaded.positions[face[2]]};
            triangle.attributes = shared;
            triangle.mesh = mesh_id;
            scene_.triangles.push_back(triangle);
        }
    }

    // A mesh named once and placed by `instance` as often as wanted: its triangles are kept once,
    // in its own coordinates, so a thousand placements cost a thousand transforms, not a thousand
    // copies.
    void define() {
        const std::string name(fields_[1]);
        for (const MeshDefinition& defined : scene_.mesh_definitions) {
            if (defined.name == name) {
                fail("a mesh named " + quoted_field(name) + " is already defined, at line " +
                     std::to_string(defined.line));
            }
        }
        const auto [file, loaded] = mesh_file(2);
        MeshDefinition definition;
        definition.name = name;
        definition.path = file.string();
        definition.line = static_cast<std::uint32_t>(line_);
        definition.triangles.reserve(loaded.faces.size());
        for (const auto& face : loaded.faces) {
            definition.triangles.push_back(
                {loaded.positions[face[0]], loaded.positions[face[1]], loaded.positions[face[2]]});
        }
        scene_.mesh_definitions.push_back(std::move(definition));
    }

    void instance() {
        const std::vector<MeshDefinition>& defined = scene_.mesh_definitions;
        const auto found =
            std::find_if(defined.begin(), defined.end(),
                         [&](const MeshDefinition& d) { return d.name == fields_[1]; });
        if (found == defined.end()) {
            fail("no mesh named " + quoted_field(fields_[1]) +
                 " is defined above this line; 'define NAME FILE' names one");
        }
        scene_.mesh_instances.push_back(
            {static_cast<std::uint32_t>(found - defined.begin()), attributes()});
    }

    // The transform stack. Each op becomes a tree node under the node in force: the OpenGL
    // right-multiplication, in memory linear in the file's length.

    void add_op(const TransformOp& op) {
        TransformNode node;
        node.parent = transform_stack_.back();
        node.op = op;
        node.identity = scene_.transforms[node.parent].identity && is_identity(op);
        ScaleRange range = scale_ranges_[node.parent];
        if (op.kind == TransformOp::Kind::scale) range = scaled(range, op.vector);
        scale_ranges_.push_back(range);
        scene_.transforms.push_back(node);
        transform_stack_.back() = static_cast<std::uint32_t>(scene_.transforms.size() - 1);
    }

    // How much the transform in force can stretch or shrink: between the products of the smallest
    // and of the largest factor of each scale in the chain (a rotation or translation changes
    // neither). Each factor alone is in range, but their product can leave it, and then M, M^-1
    // and the object-frame ray overflow or underflow as a single bad factor would.
    struct ScaleRange {
        double smallest = 1.0;
        double largest = 1.0;
    };

    ScaleRange scaled(ScaleRange range, const Vec3& factors) const {
        const Vec3 sizes = glm::abs(factors);
        range.smallest *= std::min({sizes.x, sizes.y, sizes.z});
        range.largest *= std::max({sizes.x, sizes.y, sizes.z});
        if (range.smallest < kSmallestDirection || range.largest > kLargestDirection) {
            fail("the scales in force multiply to factors between " + to_text(range.smallest) +
                 " and " + to_text(range.largest) + ", beyond 1e-150 to 1e150, where the inverse " +
                 "transform and the object-frame ray overflow or underflow");
        }
        return range;
    }

    void translate() { add_op({TransformOp::Kind::translate, vec3(1, "the offset"), 0.0}); }

    void rotate() {
        const Vec3 axis = direction(1, "the rotation axis");
        add_op({TransformOp::Kind::rotate, axis, number(4, "the angle")});
    }

    void scale() {
        const Vec3 factors = vec3(1, "a scale factor");
        for (const double factor : {factors.x, factors.y, factors.z}) {
            if (factor == 0.0) {
                fail("scale " + to_text(factors) +
                     " has a zero factor, which flattens objects and has no inverse");
            }
            // The inverse transform and the normal matrix divide by each factor.
            if (std::abs(factor) < kSmallestDirection || std::abs(factor) > kLargestDirection) {
                fail("scale " + to_text(factors) +
                     " has a factor whose inverse overflows or underflows");
            }
        }
        add_op({TransformOp::Kind::scale, factors, 0.0});
    }

    void push_transform() { transform_stack_.push_back(transform_stack_.back()); }

    void pop_transform() {
        if (transform_stack_.size() == 1) fail("popTransform without a matching pushTransform");
        transform_stack_.pop_back();
    }

    // Lights: world coordinates, whatever the transform stack holds.

    void directional() {
        const Vec3 towards_light = direction(1, "the light's direction");
        scene_.directional_lights.push_back(
            {towards_light, color(4), static_cast<std::uint32_t>(line_)});
    }

    void point() {
        scene_.point_lights.push_back(
            {vec3(1, "the position"), color(4), attenuation_, static_cast<std::uint32_t>(line_)});
    }

    void spot() {
        SpotLight light;
        light.position = vec3(1, "the position");
        light.direction = direction(4, "the spot light's axis");
        light.cutoff_degrees = number(7, "the cutoff");
        // Written so that a NaN fails too. Beyond 90 degrees the cone would light what is behind
        // the spot light, which a spot light does not do.
        if (!(light.cutoff_degrees > 0.0 && light.cutoff_degrees <= 90.0)) {
            fail("cutoff " + std::string(fields_[7]) +
                 " is out of range: the cone's half-angle must be above 0 and at most 90 degrees");
        }
        light.exponent = number(8, "the exponent");
        if (!(light.exponent >= 0.0)) {
            fail("exponent " + std::string(fields_[8]) + " must not be negative");
        }
        light.color = color(9);
        light.attenuation = attenuation_;
        light.line = static_cast<std::uint32_t>(line_);
        scene_.spot_lights.push_back(light);
    }

    // The CSE168 area light: corner a and edges ab and ac. Sampling it divides by its area
    // |ab x ac| and shades with its normal (ac x ab) / |ac x ab|, so that cross product must be a
    // direction as `direction` requires one (neither zero nor beyond the range where its length
    // is computed reliably), and ab and ac must not be parallel, by the camera's test.
    void quad_light() {
        QuadLight light;
        light.corner = vec3(1, "the corner");
        light.edge1 = vec3(4, "the edge ab");
        light.edge2 = vec3(7, "the edge ac");
        light.radiance = color(10);
        light.line = static_cast<std::uint32_t>(line_);
        const double ab_size = largest_magnitude(light.edge1);
        const double ac_size = largest_magnitude(light.edge2);
        if (ab_size == 0.0 || ac_size == 0.0) {
            fail(std::string("the light's edge ") + (ab_size == 0.0 ? "ab" : "ac") +
                 " is zero, so the light has no area");
        }
        // Scaled by their largest components, so that the products cannot overflow; written so
        // that a NaN counts as parallel.
        const Vec3 a = light.edge1 / ab_size;
        const Vec3 b = light.edge2 / ac_size;
        if (!(glm::length(glm::cross(a, b)) > kParallelSine * glm::length(a) * glm::length(b))) {
            fail("the light's edges ab " + to_text(light.edge1) + " and ac " +
                 to_text(light.edge2) + " are parallel, so the light has no area");
        }
        const double normal_size = largest_magnitude(glm::cross(light.edge1, light.edge2));
        if (!(normal_size >= kSmallestDirection && normal_size <= kLargestDirection)) {
            fail(
                "the light's area |ab x ac| is too small or too large to compute reliably "
                "(its largest component is " +
                to_text(normal_size) + ", outside 1e-150 to 1e150); scale it towards 1");
        }
        scene_.quad_lights.push_back(light);
    }

    void attenuation() {
        const Attenuation a{number(1, "the constant term"), number(2, "the linear term"),
                            number(3, "the quadratic term")};
        if (a.constant < 0 || a.linear < 0 || a.quadratic < 0) {
            fail("attenuation terms must not be negative");
        }
        if (a.constant == 0 && a.linear == 0 && a.quadratic == 0) {
            fail("attenuation 0 0 0 would divide the light by zero");
        }
        attenuation_ = a;
    }

    // Materials: the current state, given to every object made after it.

    void set_material(Color Material::*field) {
        material_.*field = color(1);
        material_id_ = kUnregistered;
    }

    void ambient() { set_material(&Material::ambient); }
    void diffuse() { set_material(&Material::diffuse); }
    void specular() { set_material(&Material::specular); }
    void emission() { set_material(&Material::emission); }

    void shininess() {
        const double s = number(1, "the shininess");
        if (s < 0) fail("shininess " + std::string(fields_[1]) + " must not be negative");
        material_.shininess = s;
        material_id_ = kUnregistered;
    }

    // Dielectrics (stage 9): material state like the colours.

    void transmission() { set_material(&Material::transmission); }

    void ior() {
        const double index = number(1, "the index of refraction");
        if (!(index > 0.0))
            fail("index of refraction " + std::string(fields_[1]) + " must be positive");
        material_.index = index;
        material_id_ = kUnregistered;
    }

    void fresnel() {
        once();
        scene_.schlick_fresnel = keyword(1, "exact|schlick") == 1;
    }

    // Sampling (stage 8). Jittered and regular patterns and stratified light samples need n x n
    // samples; the commands may come in any order, so check_sample_grids checks at the end.

    int sample_count(std::string_view what) const {
        const long n = count(1, what);
        if (n < 1) fail(std::string(what) + " must be at least 1");
        if (n > kMaxSamples) {
            fail(std::string(what) + " " + std::to_string(n) + " is above the limit of " +
                 std::to_string(kMaxSamples) +
                 ": at one ray each, a 640 x 480 render of more would not finish in a day");
        }
        return static_cast<int>(n);
    }

    void spp() {
        once();
        scene_.samples_per_pixel = sample_count("the sample count");
    }

    void pixelsampling() {
        once();
        constexpr std::array<SamplePattern, 3> patterns = {
            SamplePattern::jittered, SamplePattern::regular, SamplePattern::random};
        scene_.pixel_sampling = patterns[keyword(1, "jittered|regular|random")];
    }

    void lightsamples() {
        once();
        scene_.light_samples = sample_count("the sample count");
    }

    void lightstratify() {
        once();
        scene_.light_stratify = keyword(1, "on|off") == 0;
    }

    void seed() {
        once();
        scene_.seed = parse_unsigned64(fields_[1], {name_, line_}, "the seed");
    }

    static bool is_square(int n) {
        const int root = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
        return root * root == n;
    }

    // A non-square spp under the default pattern falls back to random sampling with a note,
    // because the CSE168 course, whose scenes must load as written, allows any spp; once a file
    // asks for jittered or regular sampling by name, it is an error.
    void check_sample_grids() {
        const int spp = scene_.samples_per_pixel;
        if (!is_square(spp) && scene_.pixel_sampling != SamplePattern::random) {
            const std::uint32_t pattern_line = line_of("pixelsampling");
            if (pattern_line != 0) {
                throw InputError(
                    name_, static_cast<int>(line_of("spp")),
                    "spp " + std::to_string(spp) + " is not a square, and 'pixelsampling " +
                        (scene_.pixel_sampling == SamplePattern::jittered ? "jittered"
                                                                          : "regular") +
                        "' on line " + std::to_string(pattern_line) +
                        " places n x n samples; give a square (4, 9, 16, ...) or 'pixelsampling "
                        "random'");
            }
            scene_.pixel_sampling = SamplePattern::random;
            scene_.notes.push_back(
                {line_of("spp"), "spp",
                 "spp " + std::to_string(spp) +
                     " is not a square, so the samples are spread at random over each pixel "
                     "rather than jittered in n x n strata; give a square for jittered sampling, "
                     "or 'pixelsampling random' to choose random sampling"});
        }
        if (scene_.light_stratify && !is_square(scene_.light_samples)) {
            throw InputError(name_, static_cast<int>(line_of("lightsamples")),
                             "lightsamples " + std::to_string(scene_.light_samples) +
                                 " is not a square, and 'lightstratify on' on line " +
                                 std::to_string(line_of("lightstratify")) +
                                 " places n x n samples on each light; give a square (4, 9, "
                                 "16, ...) or 'lightstratify off'");
        }
    }

    void background() {
        once();
        scene_.background = color(1);
    }

    // The CSE168 path tracer's settings. raystep renders direct light and mirrors (and stage 9's
    // refraction), no indirect light: each of these is read and checked so that the course's
    // scenes load, and noted where it changes nothing or renders otherwise than in the course.

    void integrator() {
        once();
        switch (keyword(1, "raytracer|direct|analyticdirect|pathtracer")) {
            case 2:
                note(
                    "'integrator analyticdirect': raystep samples each quad light "
                    "('lightsamples') rather than integrating it exactly, so soft shadows are "
                    "noisy where the course's are not");
                break;
            case 3:
                note(
                    "'integrator pathtracer': raystep renders direct light and mirror "
                    "reflection only, no indirect light, so the image is darker than a path "
                    "tracer's");
                break;
            default:
                break;
        }
    }

    void nexteventestimation() {
        once();
        keyword(1, "on|off|mis");
        note(
            "'nexteventestimation' has no effect: raystep traces no indirect paths and always "
            "samples the lights");
    }

    void russianroulette() {
        once();
        keyword(1, "on|off");
        note(
            "'russianroulette' has no effect: raystep traces no indirect paths to end at "
            "random; maxdepth bounds its mirror bounces");
    }

    void importancesampling() {
        once();
        keyword(1, "hemisphere|cosine|brdf");
        note(
            "'importancesampling' has no effect: raystep samples the lights, never directions "
            "from a surface");
    }

    void brdf() {
        keyword(1, "phong|ggx");
        note(
            "'brdf' has no effect: raystep shades every surface with the CSE167 local model "
            "(docs/stage6.md)");
    }

    void roughness() {
        const double alpha = number(1, "the roughness");
        if (!(alpha >= 0.0)) fail("roughness " + std::string(fields_[1]) + " must not be negative");
        note("'roughness' has no effect: raystep has no GGX surfaces");
    }

    void gamma() {
        once();
        const double g = number(1, "gamma");
        if (!(g > 0.0)) fail("gamma " + std::string(fields_[1]) + " must be positive");
        note("'gamma' has no effect: raystep writes colours as it computes them");
    }

    std::string name_;
    std::filesystem::path folder_;
    int line_ = 0;
    std::vector<std::string_view> fields_;
    Scene scene_;

    std::unordered_map<std::string, std::uint32_t> first_lines_;  // of once-only commands
    std::optional<OrthoWindow> ortho_;

    Material material_;
    std::uint32_t material_id_ = kUnregistered;
    Attenuation attenuation_;
    std::vector<std::uint32_t> transform_stack_{0};       // tree nodes; the root is the identity
    std::vector<ScaleRange> scale_ranges_{ScaleRange{}};  // per node of scene_.transforms

    long max_vertices_ = -1;
    long max_normal_vertices_ = -1;
    std::vector<Vec3> vertices_;
    std::vector<std::pair<Vec3, Vec3>> normal_vertices_;
};

}  // namespace

Scene parse_scene(std::string_view text, const std::string& name,
                  const std::filesystem::path& folder) {
    SceneParser parser(name, folder);
    std::string line;
    std::size_t start = 0;
    while (start < text.size()) {
        // A line ends at "\n", "\r\n" or a lone "\r" (old Mac files).
        std::size_t end = text.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = text.size();
        // A copy per line keeps each field NUL- or space-terminated for strtod.
        line.assign(text.substr(start, end - start));
        parser.parse_line(line);
        start = end + 1;
        if (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n') ++start;
    }
    return parser.finish();
}

Scene load_scene(const std::filesystem::path& path) {
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
    return parse_scene(read_text_file(path, "scene file"), path.string(), folder);
}

}  // namespace raystep
