#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/probe/probe_answer.h"

namespace raystep::grade {

// A public check as data: what the release writer (grader/grade/release.cpp) decides with the
// reference's oracle and writes into a student release as grading/public/CHECK.json, and what
// `raystep grade` reads back and runs on the student's own build. The file is JSON, one case per
// line, so that an error names the line of its case:
//
//   {"check": "stage1.unit", "stage": 1, "kind": "unit", "name": "...", "cases": [
//   {"input": "dot(...)", "call": "dot", "args": [...], "judge": {"judge": "near_number", ...},
//    "reproduce": "dot(...)"},
//   ...
//   ]}
//
// "call" and "args" are a probe query (grader/probe/README.md); "judge" a data judge
// (data_judge.h); "input" the case as a report shows it; "reproduce" what a student runs to see
// the case again, or "".

struct PublicCase {
    std::string input;
    ProbeQuery query;
    probe::Json judge;
    std::string reproduce;
};

inline constexpr const char* kSampleKind = "sample";

struct PublicCheck {
    std::string id;  ///< the rubric's key, "stage1.unit"
    int stage = 0;
    /// "unit", "render", or kSampleKind: a sample of a stage's generated cases, decided by the
    /// oracle as the grader's "stageN.oracle" cases are but drawn from seeds that check does not
    /// use, so that a student can try the kind of case the oracle holds without seeing the
    /// grader's own. A sample has no rubric entry and is worth no points.
    std::string kind;
    std::string name;
    std::vector<PublicCase> cases;
};

/// The check's file, as described above.
std::string public_check_text(const PublicCheck& check);

/// Writes public_check_text(check) to folder/ID.json.
void write_public_check(const PublicCheck& check, const std::filesystem::path& folder);

/// Reads a file public_check_text wrote. Throws InputError naming the file and line of what is
/// wrong: not JSON, a missing or ill-typed field, a judge this build does not know.
PublicCheck read_public_check(const std::filesystem::path& file);

}  // namespace raystep::grade
