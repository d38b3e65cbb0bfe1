#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grader/grade/probe_toolchain.h"

namespace raystep::grade {

/// Objects the grader compiled before, kept by everything that went into them, so that a file is
/// compiled once however often it is graded: the stubs of a stage nobody in a class has started,
/// a submission's probes built again for a batch's speed pass, the model's files that a mutant of
/// the corpus leaves as they are.
///
/// An entry is found by the compiled file's name and bytes, the compiler (its path, size and time)
/// and flags, and a digest of the grader's headers (its precompiled header by size and time); and
/// it is used only when every other file
/// that compile read (the compiler's own list of them, -MD) is as it was: a file of the
/// submission byte for byte, a system header by its size and time. The entry's folder name is a
/// hash of the first part, which only finds it: a student who made a file whose hash is another's
/// gains nothing, since the bytes are compared.
///
/// The folder is the grader's: no sandbox is shown it. An object is kept only from a compile that
/// succeeded, before any probe runs, and entries are written whole (made aside, then renamed), so
/// that graders sharing the folder (a batch's submissions at once) never read half of one.
class ObjectCache {
  public:
    /// A cache in `folder` (made when missing) for objects compiled by `toolchain` in the work
    /// folder `work`, against the headers under work/include.
    ObjectCache(std::filesystem::path folder, const ProbeToolchain& toolchain,
                std::filesystem::path work);

    /// The flags that make a compile of `object` list what it read, for keep().
    static std::vector<std::string> dependency_flags(const std::filesystem::path& object);

    /// Copies the object compiled before from `source`, with what it read as it is now, to
    /// `object`, for the sandbox's user to read; false when there is none.
    bool take(const std::filesystem::path& source, const std::filesystem::path& object) const;

    /// Keeps `object`, just compiled from `source` with dependency_flags(object).
    void keep(const std::filesystem::path& source, const std::filesystem::path& object) const;

  private:
    std::string inputs(const std::filesystem::path& source) const;
    std::filesystem::path entry(const std::string& inputs) const;
    /// What the files `read` hold now, as an entry compares them.
    std::string fingerprint(const std::vector<std::string>& read) const;

    std::filesystem::path folder_;
    std::filesystem::path work_;
    std::string toolchain_inputs_;
};

}  // namespace raystep::grade
