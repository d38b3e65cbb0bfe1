#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "base/image/image.h"

namespace raystep::grade {

/// The reference's renders that a grade made, kept in a folder of the grader's (--cache) for the
/// next grade that looks from the same eye: a batch's submissions, or the corpus's entries, which
/// share one eye seed (batch.h). The noisy render checks' sixteen renders of a view take seconds of
/// processor, the same for every submission of a class. An entry is kept under a hash of `key`
/// and holds the key's text, which must be equal for it to be read: the key names everything the
/// renders depend on (the scene's digest, the view, the size, the eye, the seeds,
/// grader_identity()).
std::optional<std::vector<Image>> kept_renders(const std::filesystem::path& folder,
                                               const std::string& key);

/// Keeps `renders` under `key`: written aside, then renamed, so that a grader reading the folder
/// at the same time never reads half of an entry. A folder that cannot be written costs only the
/// renders next time.
void keep_renders(const std::filesystem::path& folder, const std::string& key,
                  const std::vector<Image>& renders);

/// The running grader's program: its path, size and time, which change when it is built again,
/// and with it the reference's renderer; empty where they cannot be read, and then nothing should
/// be kept.
std::string grader_identity();

}  // namespace raystep::grade
