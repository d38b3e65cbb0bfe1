#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base/scene/mesh_loader.h"
#include "base/scene/scene.h"
#include "base/scene/text_fields.h"

// The scene loader's parser, shared by the files that read each group of commands:
// scene_parser.cpp (the command table and the arguments), scene_camera_commands.cpp,
// scene_geometry_commands.cpp, scene_light_commands.cpp (lights and materials),
// scene_sampling_commands.cpp and scene_path_tracer_commands.cpp. Not an interface of its own:
// load_scene and parse_scene (scene_loader.h) are.

namespace raystep::scene_parsing {

// Limits that keep a typo from exhausting memory or the stack; each is far above any real
// scene and each is reported as an error, never clamped.
inline constexpr long kMaxImageSide = 32768;
inline constexpr long kMaxImagePixels = 1L << 27;  // 128 Mpixels, 1.5 GiB of float RGB
inline constexpr long kMaxDepth = 1000;

// A direction (an up vector, a normal, an axis, a scale factor) must have its largest component
// in this range: then |v|^2 neither overflows nor underflows, and normalizing or inverting it is
// safe in anyone's code.
inline constexpr double kSmallestDirection = 1e-150;
inline constexpr double kLargestDirection = 1e150;

// Every number in a scene: the range in which products of three coordinates still fit in a
// double, the domain of the stage-3 contract.
inline constexpr double kLargestNumber = 1e100;

inline constexpr std::uint32_t kUnregistered = std::numeric_limits<std::uint32_t>::max();

/// The largest of |v.x|, |v.y|, |v.z|.
inline double largest_magnitude(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

/// Reads a scene file line by line into a Scene: parse_line for each line, then finish.
class SceneParser {
  public:
    /// `integrator` is the scene's, read before the other lines (scene_loader.cpp): it sets the
    /// dialect, and the notes of the path tracer's settings depend on it wherever it stands.
    SceneParser(std::string name, std::filesystem::path folder, Integrator integrator)
        : name_(std::move(name)), folder_(std::move(folder)) {
        scene_.path = name_;
        scene_.integrator = integrator;
        scene_.dialect =
            integrator == Integrator::raytracer ? SceneDialect::cse167 : SceneDialect::cse168;
        // The CSE168 path tracer has no ambient term: none unless the scene writes one.
        if (cse168()) material_.ambient = Color(0.0);
    }

    /// Reads one line (a command and its arguments) into the scene; throws InputError
    /// `file:line: problem` for anything wrong with it.
    void parse_line(std::string_view text);

    /// The scene's integrator: the one the constructor was given, or that an `integrator` line
    /// read since has set.
    Integrator scene_integrator() const { return scene_.integrator; }

    /// Reads line `number` of the file on its own, as parse_line would have read it there: for a
    /// line read before the others (the `integrator` that sets the dialect, scene_loader.cpp).
    void parse_line_at(int number, std::string_view text) {
        line_ = number - 1;
        parse_line(text);
    }

    /// The scene, once the checks that need the whole file (a camera, the sample grids) pass.
    Scene finish();

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

    static const std::vector<Command>& commands();
    const Command& find_command(std::string_view name) const;

    // Arguments
    [[noreturn]] void fail(const std::string& problem) const;
    double number(std::size_t k, std::string_view what) const;
    long count(std::size_t k, std::string_view what) const;
    Vec3 vec3(std::size_t first, std::string_view what) const;
    Vec3 direction(std::size_t first, std::string_view what) const;
    Color color(std::size_t first) const;
    std::size_t keyword(std::size_t k, std::string_view choices) const;
    void once();
    std::uint32_t line_of(const std::string& command) const;
    void note(const std::string& text);
    bool cse168() const { return scene_.dialect == SceneDialect::cse168; }
    /// `integrator pathtracer`, which reads the path tracer's settings.
    bool path_traced() const;
    /// finish()'s checks of a path-traced scene.
    void check_path_tracer_scene();

    // Image and camera
    void size();
    void maxdepth();
    void output();
    void rayoffset();
    void camera();
    void ortho();

    // Geometry
    ObjectAttributes attributes();
    void sphere();
    void plane();
    void broken_vertex_count(const std::string& problem);
    void maxverts();
    void maxvertnorms();
    void vertex();
    void vertexnormal();
    std::array<std::size_t, 3> indices(std::size_t available, std::string_view pile) const;
    void tri();
    void trinormal();
    std::pair<std::filesystem::path, TriangleMesh> mesh_file(std::size_t k) const;
    std::uint32_t mesh_material(const MeshMaterial& material);
    void mesh();
    void define();
    void instance();

    // The transform stack
    void add_op(const TransformOp& op);

    // How much the transform in force can stretch or shrink: between the products of the smallest
    // and of the largest factor of each scale in the chain (a rotation or translation changes
    // neither). Each factor alone is in range, but their product can leave it, and then M, M^-1
    // and the object-frame ray overflow or underflow as a single bad factor would.
    struct ScaleRange {
        double smallest = 1.0;
        double largest = 1.0;
    };

    ScaleRange scaled(ScaleRange range, const Vec3& factors) const;
    void translate();
    void rotate();
    void scale();
    void push_transform();
    void pop_transform();

    // Lights
    void directional();
    void point();
    void spot();
    void quad_light();
    void attenuation();
    void background();

    // Materials
    void set_material(Color Material::*field);
    void ambient();
    void diffuse();
    void specular();
    void emission();
    void shininess();

    // Surface detail (stage 11)
    std::int32_t texture_index(const std::filesystem::path& file, WrapMode wrap);
    std::int32_t texture_file(std::size_t k, std::size_t wrap_field);
    void set_map(std::int32_t Material::*map);
    void texture();
    void normalmap();
    void bumpmap();
    void vertexuv();
    void triuv();

    // Dielectrics (stage 9)
    void transmission();
    void ior();
    void fresnel();

    // Sampling (stage 8)
    int sample_count(std::string_view what) const;
    void spp();
    void pixelsampling();
    void lightsamples();
    void lightstratify();
    void seed();
    void check_sample_grids();

    // The CSE168 path tracer's settings that raystep does not render
    void integrator();
    void nexteventestimation();
    void russianroulette();
    void importancesampling();
    void brdf();
    void roughness();
    void gamma();

    std::string name_;
    std::filesystem::path folder_;
    int line_ = 0;
    std::vector<std::string_view> fields_;
    Scene scene_;

    std::unordered_map<std::string, std::uint32_t> first_lines_;  // of once-only commands
    std::unordered_map<std::string, std::uint32_t> first_uses_;   // of every command read
    std::optional<OrthoWindow> ortho_;

    Material material_;
    std::uint32_t material_id_ = kUnregistered;
    bool ambient_written_ = false;        // an `ambient` line was read: no default ambient since
    bool default_ambient_noted_ = false;  // the CSE168 dialect's ambient 0 is noted once
    Attenuation attenuation_;
    std::vector<std::uint32_t> transform_stack_{0};       // tree nodes; the root is the identity
    std::vector<ScaleRange> scale_ranges_{ScaleRange{}};  // per node of scene_.transforms

    long max_vertices_ = -1;
    long max_normal_vertices_ = -1;
    std::vector<Vec3> vertices_;
    std::vector<std::pair<Vec3, Vec3>> normal_vertices_;
    std::vector<std::pair<Vec3, Vec2>> uv_vertices_;
};

}  // namespace raystep::scene_parsing
