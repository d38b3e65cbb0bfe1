#include "grader/grade/submission.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "grader/grade/archive_entry_name.h"
#include "grader/grade/build_locations.h"
#include "grader/grade/mebibytes.h"
#include "grader/grade/sandbox_copies.h"
#include "grader/sandbox/sandbox.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

// One entry of a submission, a candidate for a manifest file, as raystep-unpack listed it: its
// path inside the submission (a name only, never opened as such) and, where it was taken, the
// file holding its contents.
struct Entry {
    std::string path;
    std::string kind;  ///< "file", "folder", "link", "other"
    std::uintmax_t size = 0;
    std::string target;  ///< what a link points to, as it says (never followed)
    fs::path contents;   ///< empty when it cannot be taken
};

std::size_t depth(const std::string& path) {
    return static_cast<std::size_t>(std::count(path.begin(), path.end(), '/'));
}

// Lists the submission and copies out the entries named like a manifest file, in the sandbox, as
// the sandbox's unprivileged user: raystep-unpack reads it on stdin (an archive's bytes, or a
// folder's descriptor, through which it follows no link) and writes only into work/unpacked. The
// program itself is copied into the work folder, so that the sandbox's user need not reach the
// grader's build.
std::vector<Entry> listed_entries(const fs::path& submission, bool folder,
                                  const std::set<std::string>& names, const fs::path& work,
                                  const IntakeBudget& budget, std::string& problem) {
    const fs::path tools = work / "tools";
    const fs::path unpacked = work / "unpacked";
    std::error_code ignored;
    fs::remove_all(tools, ignored);
    fs::remove_all(unpacked, ignored);
    fs::create_directories(tools);
    fs::create_directories(unpacked);
    const fs::path unpack = tools / "raystep-unpack";
    copy_file_for_sandbox(built_unpack_program(), unpack, kSharedProgram);

    std::vector<std::string> argv = {unpack.string(), unpacked.string(),
                                     std::to_string(budget.largest_file),
                                     std::to_string(budget.total)};
    argv.insert(argv.end(), names.begin(), names.end());
    SandboxPolicy policy;
    policy.read_only = {tools};
    policy.writable = unpacked;
    policy.working_directory = unpacked;
    policy.stdin_file = submission;
    policy.limits.cpu_seconds = 30;
    policy.limits.wall = std::chrono::seconds(60);
    policy.limits.file_size_bytes = budget.largest_file;
    policy.limits.output_bytes = 16u << 20;
    const SandboxRun run = run_sandboxed(argv, "", policy);

    std::vector<Entry> entries;
    std::istringstream lines(run.output);
    for (std::string line; std::getline(lines, line);) {
        if (lines.eof()) break;  // a line cut by the end of the run
        try {
            const nlohmann::json j = nlohmann::json::parse(line);
            Entry entry;
            entry.path = j.at("path").get<std::string>();
            entry.kind = j.at("kind").get<std::string>();
            entry.size =
                static_cast<std::uintmax_t>(std::max<long long>(0, j.at("size").get<long long>()));
            entry.target = j.value("target", "");
            if (j.at("taken").get<bool>()) {
                entry.contents = unpacked / std::to_string(entries.size());
            }
            entries.push_back(std::move(entry));
        } catch (const std::exception&) {
            break;
        }
    }
    const std::string said = run.errors.substr(0, run.errors.find('\n'));
    const std::string what = folder ? "folder" : "archive";
    if (!folder && run.exit_code == 3) {
        problem =
            "it is not a folder, nor an archive the grader can read (zip, tar, tar.gz, 7z, "
            "...): " +
            said;
    } else if (run.timed_out) {
        problem = "listing the " + what + " took longer than " +
                  std::to_string(static_cast<int>(policy.limits.cpu_seconds)) +
                  " s; the entries after the first " + std::to_string(entries.size()) +
                  " were not seen";
    } else if (run.exit_code != 0 || run.signal != 0) {
        problem = "the " + what + " could be read only in part (" +
                  (said.empty() ? "its reader stopped" : said) + "); the entries after the first " +
                  std::to_string(entries.size()) + " were not seen";
    }
    return entries;
}

// The links of a submission, each as "path (a link to TARGET)", for a report that must say why
// files are missing: the grader follows no link, at any depth.
std::string links_named(const std::vector<Entry>& entries) {
    std::string named;
    std::size_t count = 0;
    for (const Entry& entry : entries) {
        if (entry.kind != "link") continue;
        ++count;
        if (count <= 10) {
            named += (named.empty() ? "" : "; ") + entry.path + " (a link to " +
                     (entry.target.empty() ? "somewhere" : entry.target) + ")";
        }
    }
    if (count > 10) named += "; and " + std::to_string(count - 10) + " more";
    return named;
}

// Where an entry lands when the archive is unpacked: its path with a backslash read as '/', and
// empty and "." parts dropped ("./stages//1_vectors/vectors.cpp" ->
// "stages/1_vectors/vectors.cpp").
std::string unpacked_at(const std::string& path) {
    std::string place;
    std::string part;
    for (std::size_t i = 0; i <= path.size(); ++i) {
        if (i < path.size() && path[i] != '/' && path[i] != '\\') {
            part += path[i];
            continue;
        }
        if (!part.empty() && part != ".") place += (place.empty() ? "" : "/") + part;
        part.clear();
    }
    return place;
}

// The candidate for `file` of stage `folder`: stages/<folder>/<file> if present, else the
// shallowest file of that name; only regular files within the budget count. Of entries that land
// at the same place, only the last: unzip -o and tar write each over the one before, so it is the
// file a student sees after unpacking what they handed in, and where it cannot be taken, no
// earlier one is. Says in `note` what was passed over.
const Entry* choose(const std::vector<Entry>& entries, const std::string& folder,
                    const std::string& file, const IntakeBudget& budget, std::string& note) {
    std::vector<const Entry*> named;
    for (const Entry& entry : entries) {
        if (archive_entry_name(entry.path) == file) named.push_back(&entry);
    }
    const auto in_stage = [&](const Entry& e) {
        const std::string parent =
            e.path.substr(0, e.path.size() - std::min(e.path.size(), file.size()));
        return archive_entry_name(parent) == folder;
    };
    const Entry* best = nullptr;
    std::size_t best_copies = 1;
    std::vector<std::string> passed_over;
    // Each place's last entry and how many land there: once each, since an archive may hold a
    // hundred thousand entries of one name.
    std::map<std::string, std::pair<std::size_t, std::size_t>> last_at;
    for (std::size_t i = 0; i < named.size(); ++i) {
        auto& [last, copies] = last_at[unpacked_at(named[i]->path)];
        last = i;
        ++copies;
    }
    for (std::size_t i = 0; i < named.size(); ++i) {
        const Entry& candidate = *named[i];
        const auto [last, copies] = last_at.at(unpacked_at(candidate.path));
        if (last != i) continue;
        if (candidate.kind != "file") {
            passed_over.push_back(candidate.path + " (a " + candidate.kind + ", not a file)");
            continue;
        }
        if (candidate.size > budget.largest_file) {
            passed_over.push_back(candidate.path + " (" + mebibytes(candidate.size) +
                                  ", over the " + mebibytes(budget.largest_file) +
                                  " a source file may be)");
            continue;
        }
        if (candidate.contents.empty()) {
            passed_over.push_back(candidate.path + " (past the " + mebibytes(budget.total) +
                                  " a submission may unpack)");
            continue;
        }
        if (!best || (in_stage(candidate) && !in_stage(*best)) ||
            (in_stage(candidate) == in_stage(*best) && depth(candidate.path) < depth(best->path))) {
            best = &candidate;
            best_copies = copies;
        }
    }
    for (const std::string& passed : passed_over)
        note += (note.empty() ? "" : "; ") + std::string("left out ") + passed;
    if (best && named.size() > 1) {
        note += (note.empty() ? "" : "; ") + file + ": " + std::to_string(named.size()) +
                " entries of that name; took " +
                (best_copies > 1 ? "the last of the " + std::to_string(best_copies) + " at " +
                                       unpacked_at(best->path) + ", the one unpacking leaves"
                                 : best->path);
    }
    return best;
}

}  // namespace

std::string submission_name(const fs::path& path) {
    std::string name = path.filename().string();
    for (const char* extension :
         {".tar.gz", ".tar.bz2", ".tar.xz", ".tgz", ".zip", ".tar", ".7z"}) {
        const std::string ending = extension;
        if (name.size() > ending.size() &&
            name.compare(name.size() - ending.size(), ending.size(), ending) == 0) {
            name.resize(name.size() - ending.size());
            break;
        }
    }
    for (char& c : name) {
        const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
        if (!safe) c = '_';
    }
    name.erase(0, name.find_first_not_of('.'));
    if (name.size() > 100) name.resize(100);
    return name.empty() ? "submission" : name;
}

Submission take_submission(const fs::path& path, const std::vector<StageManifest>& manifests,
                           const fs::path& work, const IntakeBudget& budget) {
    Submission submission;
    submission.name = submission_name(path);
    submission.tree = work / "submission";

    std::set<std::string> names;
    for (const StageManifest& manifest : manifests)
        names.insert(manifest.files.begin(), manifest.files.end());
    std::vector<Entry> entries;
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (fs::is_directory(status) || fs::is_regular_file(status)) {
        entries =
            listed_entries(path, fs::is_directory(status), names, work, budget, submission.problem);
    } else if (fs::exists(status)) {
        submission.problem = "it is neither a folder nor a file";
    } else {
        submission.problem = "it does not exist";
    }

    std::uintmax_t taken = 0;
    for (const StageManifest& manifest : manifests) {
        SubmittedStage stage;
        stage.manifest = manifest;
        const fs::path folder = submission.tree / "stages" / manifest.folder;
        fs::create_directories(folder);
        for (const std::string& file : manifest.files) {
            std::string note;
            const Entry* found = choose(entries, manifest.folder, file, budget, note);
            if (found && taken + found->size > budget.total) {
                note += (note.empty() ? "" : "; ") + std::string("left out ") + found->path +
                        " (past the " + mebibytes(budget.total) + " a submission may bring)";
                found = nullptr;
            }
            if (found) {
                try {
                    copy_file_for_sandbox(found->contents, folder / file, kSharedFile,
                                          budget.largest_file);
                } catch (const std::runtime_error& copy_error) {
                    note += (note.empty() ? "" : "; ") + std::string("left out ") + found->path +
                            " (" + copy_error.what() + ")";
                    found = nullptr;
                }
            }
            if (!note.empty()) stage.notes.push_back(note);
            if (!found) {
                stage.missing.push_back(file);
                continue;
            }
            taken += found->size;
            stage.files.push_back(folder / file);
        }
        submission.stages.push_back(stage);
    }
    fs::remove_all(work / "unpacked", error);
    if (submission.problem.empty() && taken == 0 && !manifests.empty()) {
        submission.problem = "it holds none of the files the stages' manifests name (such as " +
                             manifests.front().files.front() + ")";
    }
    // Files are missing: any link may be why, since none is followed
    const bool missing = std::any_of(submission.stages.begin(), submission.stages.end(),
                                     [](const SubmittedStage& s) { return !s.missing.empty(); });
    const std::string links = links_named(entries);
    if (missing && !links.empty()) {
        submission.problem += (submission.problem.empty() ? "" : "; ") +
                              std::string("the grader follows no link, and these were left: ") +
                              links;
    }
    return submission;
}

}  // namespace raystep::grade
