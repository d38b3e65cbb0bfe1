#pragma once

// The reference grid's cell lists, in compressed form: one array of primitive ids, cell after
// cell, and one array of offsets saying where each cell's ids begin. Two allocations in all,
// where a vector per cell would make up to 256^3 of them.

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "solutions/4_accel/grid_layout.h"

namespace raystep {

/// Cell c holds the ids ids[offsets[c]] to ids[offsets[c + 1] - 1], in increasing order.
struct GridCells {
    std::vector<std::size_t> offsets;
    std::vector<std::uint32_t> ids;

    const std::uint32_t* begin(std::size_t cell) const { return ids.data() + offsets[cell]; }
    const std::uint32_t* end(std::size_t cell) const { return ids.data() + offsets[cell + 1]; }
};

/// Enters primitive k (box `boxes[k]`) in every cell that its box, grown by `margin` on every
/// side, overlaps; the closed box, so a box that touches a plane between cells goes in both. An
/// empty box (a primitive with no extent to bound, such as a sphere of negative radius) goes
/// nowhere. uniform_grid.cpp says why the margin.
inline GridCells fill_cells(const GridLayout& grid, const std::vector<Aabb>& boxes, double margin) {
    // The cells a box overlaps: a range along each axis
    struct CellRange {
        glm::ivec3 low;
        glm::ivec3 high;
    };
    std::vector<CellRange> ranges(boxes.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        if (boxes[k].empty()) {
            ranges[k] = {glm::ivec3(0), glm::ivec3(-1)};
            continue;
        }
        for (int axis = 0; axis < 3; ++axis) {
            ranges[k].low[axis] = grid.cell_of(boxes[k].min[axis] - margin, axis);
            ranges[k].high[axis] = grid.cell_of(boxes[k].max[axis] + margin, axis);
        }
    }
    const auto for_each_cell = [&](const CellRange& range, auto&& action) {
        for (int z = range.low.z; z <= range.high.z; ++z) {
            for (int y = range.low.y; y <= range.high.y; ++y) {
                for (int x = range.low.x; x <= range.high.x; ++x)
                    action(grid.index({x, y, z}));
            }
        }
    };

    // Counting pass: cell c's count goes to offsets[c + 1], so that the running sum turns the
    // counts into where each cell begins
    GridCells cells;
    cells.offsets.assign(grid.cell_count() + 1, 0);
    for (const CellRange& range : ranges) {
        for_each_cell(range, [&](std::size_t cell) { ++cells.offsets[cell + 1]; });
    }
    std::partial_sum(cells.offsets.begin(), cells.offsets.end(), cells.offsets.begin());

    // Filling pass, in id order, so that each cell's ids come out sorted
    cells.ids.resize(cells.offsets.back());
    std::vector<std::size_t> next(cells.offsets.begin(), cells.offsets.end() - 1);
    for (std::size_t k = 0; k < ranges.size(); ++k) {
        for_each_cell(ranges[k], [&](std::size_t cell) {
            cells.ids[next[cell]++] = static_cast<std::uint32_t>(k);
        });
    }
    return cells;
}

}  // namespace raystep
