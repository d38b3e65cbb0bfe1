#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "base/errors/input_error.h"
#include "base/scene/mesh_loader.h"
#include "base/scene/text_fields.h"

namespace raystep {

namespace {

// The OFF file line by line, skipping blank and comment lines; every record of the format is one
// line, so a short line is an error at that line, never a borrow from the next.
class OffLines {
  public:
    OffLines(std::istream& in, const std::string& file) : in_(in), file_(file) {}

    /// The next line's fields; throws when the file ends before `what`.
    const std::vector<std::string_view>& next(std::string_view what) {
        if (advance()) return fields_;
        throw InputError(file_, line_, "the file ends before " + std::string(what));
    }

    /// The next line's fields, record `k` of `total` of a `kind` ("vertex", "face"). The message
    /// is only built when the file ends: a mesh has a hundred thousand records.
    const std::vector<std::string_view>& next_record(std::string_view kind, long k, long total) {
        if (advance()) return fields_;
        throw InputError(file_, line_,
                         "the file ends before " + std::string(kind) + " " + std::to_string(k) +
                             " of " + std::to_string(total));
    }

    /// Requires at least `count` fields on the current line.
    void require(std::size_t count, std::string_view what) const {
        if (fields_.size() < count) {
            fail(std::string(what) + " needs " + std::to_string(count) +
                 " numbers, this line has " + std::to_string(fields_.size()));
        }
    }

    double number(std::size_t k, std::string_view what) const {
        return parse_finite_number(fields_[k], {file_, line_}, what);
    }

    long count(std::size_t k, std::string_view what) const {
        return parse_count(fields_[k], {file_, line_}, what);
    }

    [[noreturn]] void fail(const std::string& problem) const {
        throw InputError(file_, line_, problem);
    }

  private:
    bool advance() {
        while (std::getline(in_, text_)) {
            ++line_;
            split_fields(text_, fields_);
            if (!fields_.empty()) return true;
        }
        return false;
    }

    std::istream& in_;
    const std::string& file_;
    std::string text_;
    std::vector<std::string_view> fields_;
    int line_ = 0;
};

// The shortest a vertex line ("0 0 0\n") and a face line ("3 0 1 2\n") can be: a header that
// promises more records than the file has bytes for is wrong, and must not make us allocate.
constexpr std::uintmax_t kShortestVertexLine = 6;
constexpr std::uintmax_t kShortestFaceLine = 8;

}  // namespace

// OFF as CGAL and Geomview write it: "OFF", then "vertices faces edges" (on the same line or the
// next), then one line "x y z" per vertex and one line "n i0 ... i(n-1)" per face, vertices
// numbered from 0; anything after those numbers on a line (a colour) is ignored.
TriangleMesh load_off_mesh(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name, 0, "cannot open the mesh file");
    std::error_code error;
    const std::uintmax_t file_size = std::filesystem::file_size(path, error);
    OffLines lines(in, name);

    // Header
    std::vector<std::string_view> fields = lines.next("the 'OFF' keyword");
    if (fields[0] != "OFF") {
        lines.fail("expected 'OFF' at the start, found " + quoted_field(fields[0]));
    }
    std::size_t first_count = 1;
    if (fields.size() == 1) {
        fields = lines.next("the vertex, face and edge counts");
        first_count = 0;
    }
    lines.require(first_count + 3, "the header");
    const long vertex_count = lines.count(first_count, "the vertex count");
    const long face_count = lines.count(first_count + 1, "the face count");
    lines.count(first_count + 2, "the edge count");
    if (!error && static_cast<std::uintmax_t>(vertex_count) * kShortestVertexLine +
                          static_cast<std::uintmax_t>(face_count) * kShortestFaceLine >
                      file_size) {
        lines.fail("the header promises " + std::to_string(vertex_count) + " vertices and " +
                   std::to_string(face_count) + " faces, more than the file's " +
                   std::to_string(file_size) + " bytes can hold");
    }

    // Vertices
    TriangleMesh mesh;
    mesh.positions.reserve(static_cast<std::size_t>(vertex_count));
    for (long v = 0; v < vertex_count; ++v) {
        lines.next_record("vertex", v, vertex_count);
        lines.require(3, "a vertex");
        mesh.positions.push_back({lines.number(0, "a vertex coordinate"),
                                  lines.number(1, "a vertex coordinate"),
                                  lines.number(2, "a vertex coordinate")});
    }

    // Faces, fanned into triangles
    mesh.faces.reserve(static_cast<std::size_t>(face_count));
    std::vector<std::uint32_t> polygon;
    for (long f = 0; f < face_count; ++f) {
        fields = lines.next_record("face", f, face_count);
        const long corners = lines.count(0, "a face's vertex count");
        if (corners < 3) {
            lines.fail("a face needs at least 3 vertices, this one has " + std::to_string(corners));
        }
        if (static_cast<std::size_t>(corners) >= fields.size()) {
            lines.fail("a face of " + std::to_string(corners) + " vertices lists only " +
                       std::to_string(fields.size() - 1));
        }
        polygon.clear();
        for (long c = 1; c <= corners; ++c) {
            const long index = lines.count(static_cast<std::size_t>(c), "a face's vertex index");
            if (index >= vertex_count) {
                lines.fail("vertex index " + std::to_string(index) +
                           " is out of range: the file has " + std::to_string(vertex_count) +
                           " vertices, numbered from 0");
            }
            polygon.push_back(static_cast<std::uint32_t>(index));
        }
        append_triangle_fan(mesh, polygon);
    }
    return mesh;
}

}  // namespace raystep
