// The zip `raystep submit` writes, taken as the grader takes a submission: unpacked by
// raystep-unpack (libarchive) in the sandbox, every manifest file found, byte for byte. The files
// are this repository's stage files, the ones a student's zip holds.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/submit/stored_zip.h"
#include "app/submit/submission_files.h"
#include "base/testing/catch.h"
#include "grader/grade/stage_manifests.h"
#include "grader/grade/submission.h"
#include "grader/grade/work_folder.h"
#include "grader/sandbox/tests/sandbox_test_support.h"

using namespace raystep::grade;
using raystep::grade::testing::read_text;
using raystep::grade::testing::TempFolder;

namespace fs = std::filesystem;

TEST_CASE("raystep submit: its files are those the grader's manifests name, in the same order",
          "[intake]") {
    std::vector<std::string> grader_names;
    for (const StageManifest& manifest : read_stage_manifests(RAYSTEP_SOURCE_DIR)) {
        for (const std::string& file : manifest.files)
            grader_names.push_back("stages/" + manifest.folder + "/" + file);
    }
    std::vector<std::string> submit_names;
    for (const raystep::SubmissionFile& file : raystep::submission_files(RAYSTEP_SOURCE_DIR))
        submit_names.push_back(file.name);
    CHECK(submit_names == grader_names);
}

TEST_CASE("raystep submit: the grader takes every manifest file from its zip, byte for byte",
          "[intake]") {
    const TempFolder folder(0755);
    std::vector<raystep::ZipEntry> entries;
    for (const raystep::SubmissionFile& file : raystep::submission_files(RAYSTEP_SOURCE_DIR))
        entries.push_back({file.name, read_text(file.path)});
    const fs::path zip = folder.path() / "submission.zip";
    std::ofstream(zip, std::ios::binary) << raystep::stored_zip(entries);
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission =
        take_submission(zip, read_stage_manifests(RAYSTEP_SOURCE_DIR), work.path());
    CHECK(submission.problem.empty());
    std::size_t taken = 0;
    for (const SubmittedStage& stage : submission.stages) {
        CAPTURE(stage.manifest.folder);
        CHECK(stage.missing.empty());
        CHECK(stage.notes.empty());
        for (const fs::path& file : stage.files) {
            const std::string name =
                "stages/" + stage.manifest.folder + "/" + file.filename().string();
            CAPTURE(name);
            CHECK(read_text(file) == read_text(fs::path(RAYSTEP_SOURCE_DIR) / name));
            ++taken;
        }
    }
    CHECK(taken == entries.size());
}
