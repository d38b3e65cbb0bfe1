#include "grading/3_intersect/closed_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

namespace raystep {

namespace {

// Fills in the edges and fans from the faces.
void add_adjacency(ClosedMesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> edge_of;
    mesh.vertex_faces.assign(mesh.vertices.size(), {});
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.faces[f][k];
            const std::uint32_t b = mesh.faces[f][(k + 1) % 3];
            mesh.vertex_faces[a].push_back(f);
            const auto key = std::minmax(a, b);
            const auto found = edge_of.find(key);
            if (found == edge_of.end()) {
                edge_of[key] = mesh.edges.size();
                mesh.edges.push_back({key.first, key.second, {f, f}});
            } else {
                mesh.edges[found->second].faces[1] = f;
            }
        }
    }
}

}  // namespace

ClosedMesh icosphere(int levels) {
    ClosedMesh mesh;
    // The icosahedron: the cyclic permutations of (0, +-1, +-phi).
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    const Vec3 corners[12] = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                              {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                              {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
    for (const Vec3& c : corners)
        mesh.vertices.push_back(glm::normalize(c));
    mesh.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                  {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                  {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                  {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

    // Split each face in four; a midpoint shared by two faces is made once.
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint_of;
        const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto found = midpoint_of.find(key);
            if (found != midpoint_of.end()) return found->second;
            mesh.vertices.push_back(glm::normalize(mesh.vertices[a] + mesh.vertices[b]));
            const auto index = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
            midpoint_of[key] = index;
            return index;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        for (const auto& [a, b, c] : mesh.faces) {
            const std::uint32_t ab = midpoint(a, b);
            const std::uint32_t bc = midpoint(b, c);
            const std::uint32_t ca = midpoint(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({b, bc, ab});
            finer.push_back({c, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        mesh.faces = std::move(finer);
    }
    add_adjacency(mesh);
    return mesh;
}

}  // namespace raystep
