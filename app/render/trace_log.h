#pragma once

#include <string>
#include <vector>

namespace raystep {

/// The record of one pixel's computation that `raystep trace` prints: one line per step, in the
/// order the renderer took them. Lines hold numbers as base/math/to_text.h prints them, so the
/// trace of two builds can be compared line by line.
class TraceLog {
  public:
    void add(std::string line) { lines_.push_back(std::move(line)); }
    const std::vector<std::string>& lines() const { return lines_; }

  private:
    std::vector<std::string> lines_;
};

}  // namespace raystep
