#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors/input_error.h"
#include "core/scene/mesh_loader.h"
#include "core/scene/text_fields.h"

namespace raystep {

namespace {

// OFF fields flow freely across lines, but a face ends at its line's end (what follows its
// indices is an optional colour), so the reader hands out fields and can drop the rest of a line.
class OffFields {
  public:
    OffFields(std::istream& in, const std::string& file) : in_(in), file_(file) {}

    int line() const { return line_; }

    std::string_view next(std::string_view what) {
        while (next_field_ == fields_.size()) {
            if (!std::getline(in_, text_)) {
                throw InputError(file_, line_, "the file ends before " + std::string(what));
            }
            ++line_;
            split_fields(text_, fields_);
            next_field_ = 0;
        }
        return fields_[next_field_++];
    }

    double next_number(std::string_view what) {
        const std::string_view field = next(what);
        return parse_finite_number(field, {file_, line_}, what);
    }

    long next_count(std::string_view what) {
        const std::string_view field = next(what);
        return parse_count(field, {file_, line_}, what);
    }

    void skip_rest_of_line() { next_field_ = fields_.size(); }

  private:
    std::istream& in_;
    const std::string& file_;
    std::string text_;
    std::vector<std::string_view> fields_;
    std::size_t next_field_ = 0;
    int line_ = 0;
};

}  // namespace

// OFF as CGAL and Geomview write it: "OFF", then "vertices faces edges", then a line "x y z"
// per vertex and a line "n i0 ... i(n-1) [colour]" per face, vertices numbered from 0.
TriangleMesh load_off_mesh(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name, 0, "cannot open the mesh file");
    OffFields fields(in, name);

    // Header
    const std::string_view keyword = fields.next("the 'OFF' keyword");
    if (keyword != "OFF") {
        throw InputError(name, fields.line(),
                         "expected 'OFF' at the start, found '" + std::string(keyword) + "'");
    }
    const long vertex_count = fields.next_count("the vertex count");
    const long face_count = fields.next_count("the face count");
    fields.next_count("the edge count");

    // Vertices
    TriangleMesh mesh;
    mesh.positions.reserve(static_cast<std::size_t>(vertex_count));
    for (long v = 0; v < vertex_count; ++v) {
        const double x = fields.next_number("a vertex coordinate");
        const double y = fields.next_number("a vertex coordinate");
        const double z = fields.next_number("a vertex coordinate");
        mesh.positions.push_back({x, y, z});
        fields.skip_rest_of_line();
    }

    // Faces, fanned into triangles
    mesh.faces.reserve(static_cast<std::size_t>(face_count));
    std::vector<std::uint32_t> polygon;
    for (long f = 0; f < face_count; ++f) {
        const long corners = fields.next_count("a face's vertex count");
        if (corners < 3) {
            throw InputError(
                name, fields.line(),
                "a face needs at least 3 vertices, this one has " + std::to_string(corners));
        }
        polygon.clear();
        for (long c = 0; c < corners; ++c) {
            const long index = fields.next_count("a face's vertex index");
            if (index >= vertex_count) {
                throw InputError(name, fields.line(),
                                 "vertex index " + std::to_string(index) +
                                     " is out of range: the file has " +
                                     std::to_string(vertex_count) + " vertices, numbered from 0");
            }
            polygon.push_back(static_cast<std::uint32_t>(index));
        }
        fields.skip_rest_of_line();
        append_triangle_fan(mesh, polygon);
    }
    return mesh;
}

}  // namespace raystep
