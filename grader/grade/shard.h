#pragma once

#include <cstddef>
#include <string>

namespace raystep::grade {

/// The I-th of N slices of a class (`raystep-grade batch --shard I/N`), so that N machines, or a
/// Slurm job array, or a CI matrix grade a class together. Submission k of the class, in name
/// order from 0, belongs to shard k mod N + 1: a round robin, so that each shard gets as many
/// submissions as the others within one whatever the names.
struct Shard {
    int index = 1;  ///< I, from 1
    int count = 1;  ///< N; 1/1 is the whole class

    bool holds(std::size_t submission) const {
        return static_cast<int>(submission % static_cast<std::size_t>(count)) == index - 1;
    }
    std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

/// Reads "I/N" with 1 <= I <= N; throws std::invalid_argument saying what is wrong otherwise.
Shard parse_shard(const std::string& text);

}  // namespace raystep::grade
