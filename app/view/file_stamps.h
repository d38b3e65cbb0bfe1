#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace raystep {

/// The last-write time and size of some files when this was made, to tell when one of them has
/// changed: a scene saved in an editor, a program rebuilt. A file that is missing counts as a
/// state of its own, so one that appears or goes is a change too.
class FileStamps {
  public:
    FileStamps() = default;
    explicit FileStamps(std::vector<std::filesystem::path> files);

    /// True when any file differs from when the stamps were taken.
    bool changed() const;

    const std::vector<std::filesystem::path>& files() const { return files_; }

  private:
    std::vector<std::filesystem::path> files_;
    std::vector<std::string> stamps_;
};

}  // namespace raystep
