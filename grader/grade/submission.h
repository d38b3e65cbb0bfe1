#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "grader/grade/probe_toolchain.h"
#include "grader/grade/stage_manifests.h"

namespace raystep::grade {

/// One stage's files as found in a submission.
struct SubmittedStage {
    StageManifest manifest;
    /// The manifest's files, copied into the work folder as stages/<folder>/<file>.
    std::vector<std::filesystem::path> files;
    std::vector<std::string> missing;  ///< manifest files the submission does not have
    std::vector<std::string> notes;    ///< e.g. which of two candidates was taken
};

struct Submission {
    std::string name;            ///< the folder's or zip's name, for reports and the class CSV
    std::filesystem::path tree;  ///< work/submission: stages/<folder>/<file> for every file found
    std::vector<SubmittedStage> stages;
};

/// Takes the manifest files, and only those, from a submission folder or zip file, into
/// work/submission. A file is found at stages/<folder>/<file> anywhere in the submission, or else
/// as <file> anywhere (the shallowest); symbolic links are never followed and files over 1 MiB
/// are left out, so that a submission can only hand in its own text. A zip file is unpacked by
/// `cmake -E tar` inside the sandbox. Throws std::runtime_error when the path is neither a folder
/// nor a zip file, or the zip cannot be unpacked.
Submission take_submission(const std::filesystem::path& path,
                           const std::vector<StageManifest>& manifests,
                           const std::filesystem::path& work, const ProbeToolchain& toolchain);

}  // namespace raystep::grade
