#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace raystep {

/// A one-line progress bar on a terminal, redrawn in place:
/// `scene.png [##########----------]  50%  1.2 s`, and with a unit the count done too,
/// `scene.png [##########----------]  50%  1.2 s  2457600 of 4915200 samples`. Draws nothing
/// when `enabled` is false, so logs and pipes stay clean.
class ProgressBar {
  public:
    ProgressBar(std::string label, std::size_t total, bool enabled, std::FILE* out = stderr,
                std::string unit = "");

    /// Redraws with `done` of `total` finished.
    void update(std::size_t done);

    /// Draws 100% and ends the line.
    void finish();

    /// Ends the line where the bar stopped, for a render that failed.
    void abandon();

  private:
    std::string label_;
    std::string unit_;
    std::size_t total_;
    bool enabled_;
    std::FILE* out_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace raystep
