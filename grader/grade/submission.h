#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "grader/grade/probe_toolchain.h"
#include "grader/grade/stage_manifests.h"

namespace raystep::grade {

/// One stage's files as found in a submission.
struct SubmittedStage {
    StageManifest manifest;
    /// The manifest's files, copied into the work folder as submission/stages/<folder>/<file>.
    std::vector<std::filesystem::path> files;
    std::vector<std::string> missing;  ///< manifest files the submission does not have
    std::vector<std::string> notes;    ///< e.g. which of two candidates was taken, or why none
};

struct Submission {
    std::string name;            ///< the folder's or archive's name, for reports and the class CSV
    std::filesystem::path tree;  ///< work/submission: stages/<folder>/<file> for every file found
    std::vector<SubmittedStage> stages;
    /// Why files could not be taken, in words ("not an archive ...", "over the budget ..."), or
    /// empty. The stages whose files are missing then fail to compile, and every report says why.
    std::string problem;
};

/// What a submission may bring in. A source file is text a student wrote: far below a mebibyte.
/// The total bounds what an archive of many copies can unpack.
struct IntakeBudget {
    std::uintmax_t largest_file = std::uintmax_t{1} << 20;
    std::uintmax_t total = std::uintmax_t{32} << 20;
};

/// Takes the manifest files, and only those, from a submission into work/submission. The
/// submission may be a folder, or a file: an archive of any kind libarchive reads, whatever its
/// name says. Either is read the same way: raystep-unpack, run in the sandbox as its unprivileged
/// user, lists it and copies out only entries named like a manifest file; a folder it reads
/// through a descriptor the grader opened, one name at a time, following no link at any depth.
/// A file is found at stages/<folder>/<file> anywhere in the submission, or else as <file>
/// anywhere (the shallowest). Links of every kind (a linked `stages` or stage folder too), special
/// files and files over the budget are never taken, and when files are missing `problem` names
/// every link; names never reach the file system, so no name can place a file outside the work
/// folder. Never throws for what the submission is or holds: a path that is missing, not an
/// archive, unreadable, broken partway or over the budget is said in `problem`, with every file
/// that could be taken. Throws only for the grader's own problems (raystep-unpack missing).
Submission take_submission(const std::filesystem::path& path,
                           const std::vector<StageManifest>& manifests,
                           const std::filesystem::path& work, const IntakeBudget& budget = {});

/// A name for the submission at `path` that is safe as one folder's name: its file name without
/// the archive's extension, with every character outside [A-Za-z0-9._-] replaced by '_', no
/// leading '.', at most 100 characters; "submission" where nothing is left.
std::string submission_name(const std::filesystem::path& path);

}  // namespace raystep::grade
