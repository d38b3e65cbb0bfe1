#include "grading/4_accel/structure_json.h"

#include <stdexcept>

namespace raystep::probe {

namespace {

// A list of indices: whole numbers from 0, nothing else.
std::vector<std::size_t> indices_from(const Json& j) {
    if (!j.is_array()) throw std::invalid_argument("a list of indices must be an array");
    std::vector<std::size_t> indices;
    indices.reserve(j.size());
    for (const Json& index : j) {
        if (!index.is_number_unsigned()) {
            throw std::invalid_argument("an index must be a whole number from 0, not " +
                                        index.dump());
        }
        indices.push_back(index.get<std::size_t>());
    }
    return indices;
}

}  // namespace

Json bvh_nodes(const std::vector<BvhNodeData>& nodes) {
    Json list = Json::array();
    for (const BvhNodeData& node : nodes) {
        list.push_back({{"min", vec3(node.box.min)},
                        {"max", vec3(node.box.max)},
                        {"children", node.children},
                        {"primitives", node.primitives}});
    }
    return list;
}

std::vector<BvhNodeData> bvh_nodes_from(const Json& j) {
    if (!j.is_array()) throw std::invalid_argument("a BVH's nodes must be an array");
    std::vector<BvhNodeData> nodes;
    nodes.reserve(j.size());
    for (const Json& node : j) {
        nodes.push_back({{vec3_from(field(node, "min")), vec3_from(field(node, "max"))},
                         indices_from(field(node, "children")),
                         indices_from(field(node, "primitives"))});
    }
    return nodes;
}

Json uniform_grid_data(const UniformGridData& grid) {
    Json cells = Json::array();
    for (const std::vector<std::size_t>& cell : grid.cells)
        cells.push_back(cell);
    return {{"min", vec3(grid.bounds.min)},
            {"max", vec3(grid.bounds.max)},
            {"resolution", {grid.resolution.x, grid.resolution.y, grid.resolution.z}},
            {"cells", cells}};
}

UniformGridData uniform_grid_data_from(const Json& j) {
    UniformGridData grid;
    grid.bounds = {vec3_from(field(j, "min")), vec3_from(field(j, "max"))};
    const Json& resolution = field(j, "resolution");
    if (!resolution.is_array() || resolution.size() != 3) {
        throw std::invalid_argument("a grid's resolution must be three whole numbers");
    }
    grid.resolution = {integer_from(resolution[0]), integer_from(resolution[1]),
                       integer_from(resolution[2])};
    const Json& cells = field(j, "cells");
    if (!cells.is_array()) throw std::invalid_argument("a grid's cells must be an array");
    grid.cells.reserve(cells.size());
    for (const Json& cell : cells)
        grid.cells.push_back(indices_from(cell));
    return grid;
}

}  // namespace raystep::probe
