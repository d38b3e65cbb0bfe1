// Taking a submission's files (grader/grade/submission.h) from whatever a student hands in:
// archives of every kind and name, entries too large, links, hostile names, nothing at all. Each
// archive is written here with libarchive, so that every case is exactly what it says.
#include <archive.h>
#include <archive_entry.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "base/testing/catch.h"
#include "grader/grade/batch.h"
#include "grader/grade/submission.h"
#include "grader/grade/work_folder.h"
#include "grader/sandbox/tests/sandbox_test_support.h"

using namespace raystep::grade;
using raystep::grade::testing::read_text;
using raystep::grade::testing::TempFolder;

namespace fs = std::filesystem;

namespace {

// Two stages of two files and one: enough to see which were taken.
const std::vector<StageManifest> kManifests = {{1, "1_vectors", {"vectors.cpp"}},
                                               {3, "3_intersect", {"sphere.cpp", "plane.cpp"}}};

struct ArchiveEntry {
    std::string path;
    std::string contents;
    std::string hardlink;  ///< a hard link to this path instead of contents
    std::string symlink;   ///< a symbolic link to this target instead of contents
};

enum class Format { zip, tar_gz, pax };

// Writes `entries` into an archive of `format` at `file`.
void write_archive(const fs::path& file, Format format, const std::vector<ArchiveEntry>& entries) {
    archive* writer = archive_write_new();
    if (format == Format::zip) {
        archive_write_set_format_zip(writer);
    } else {
        archive_write_set_format_pax_restricted(writer);
        if (format == Format::tar_gz) archive_write_add_filter_gzip(writer);
    }
    REQUIRE(archive_write_open_filename(writer, file.c_str()) == ARCHIVE_OK);
    for (const ArchiveEntry& e : entries) {
        archive_entry* entry = archive_entry_new();
        archive_entry_set_pathname(entry, e.path.c_str());
        archive_entry_set_perm(entry, 0644);
        if (!e.hardlink.empty()) {
            archive_entry_set_filetype(entry, AE_IFREG);
            archive_entry_set_hardlink(entry, e.hardlink.c_str());
            archive_entry_set_size(entry, 0);
        } else if (!e.symlink.empty()) {
            archive_entry_set_filetype(entry, AE_IFLNK);
            archive_entry_set_symlink(entry, e.symlink.c_str());
        } else {
            archive_entry_set_filetype(entry, AE_IFREG);
            archive_entry_set_size(entry, static_cast<la_int64_t>(e.contents.size()));
        }
        // A warning (a name that is not UTF-8) still writes the entry, as the test wants.
        REQUIRE(archive_write_header(writer, entry) >= ARCHIVE_WARN);
        if (!e.contents.empty()) {
            REQUIRE(archive_write_data(writer, e.contents.data(), e.contents.size()) ==
                    static_cast<la_ssize_t>(e.contents.size()));
        }
        archive_entry_free(entry);
    }
    REQUIRE(archive_write_close(writer) == ARCHIVE_OK);
    archive_write_free(writer);
}

std::vector<ArchiveEntry> complete_stages(const std::string& prefix) {
    return {{prefix + "stages/1_vectors/vectors.cpp", "// vectors", "", ""},
            {prefix + "stages/3_intersect/sphere.cpp", "// sphere", "", ""},
            {prefix + "stages/3_intersect/plane.cpp", "// plane", "", ""}};
}

// The submission's files as taken: "1_vectors/vectors.cpp" -> its text.
std::map<std::string, std::string> taken(const Submission& submission) {
    std::map<std::string, std::string> files;
    for (const SubmittedStage& stage : submission.stages) {
        for (const fs::path& file : stage.files) {
            files[stage.manifest.folder + "/" + file.filename().string()] = read_text(file);
        }
    }
    return files;
}

std::string notes(const Submission& submission) {
    std::string text;
    for (const SubmittedStage& stage : submission.stages) {
        for (const std::string& note : stage.notes)
            text += note + "\n";
    }
    return text;
}

// The files under `folder`, by path relative to it.
std::vector<std::string> files_under(const fs::path& folder) {
    std::vector<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        if (!entry.is_directory()) files.push_back(fs::relative(entry.path(), folder).string());
    }
    return files;
}

}  // namespace

TEST_CASE("take_submission: every kind of archive gives the same files, whatever its name says",
          "[intake]") {
    const TempFolder folder(0755);
    const Format format = GENERATE(Format::zip, Format::tar_gz, Format::pax);
    const std::string name = GENERATE(std::string("work.zip"), std::string("work.tar.gz"),
                                      std::string("work"), std::string("work.pdf"));
    CAPTURE(static_cast<int>(format), name);
    const fs::path archive = folder.path() / name;
    write_archive(archive, format, complete_stages("raystep-main/"));
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission = take_submission(archive, kManifests, work.path());
    CHECK(submission.problem.empty());
    CHECK(taken(submission) ==
          std::map<std::string, std::string>{{"1_vectors/vectors.cpp", "// vectors"},
                                             {"3_intersect/sphere.cpp", "// sphere"},
                                             {"3_intersect/plane.cpp", "// plane"}});
}

TEST_CASE("take_submission: a build product of 20 MiB beside the sources is passed over",
          "[intake]") {
    const TempFolder folder(0755);
    std::vector<ArchiveEntry> entries = complete_stages("");
    entries.push_back(
        {"build/release/bin/raystep", std::string(std::size_t{20} << 20, 'x'), "", ""});
    const fs::path archive = folder.path() / "repository.zip";
    write_archive(archive, Format::zip, entries);
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission = take_submission(archive, kManifests, work.path());
    CHECK(submission.problem.empty());
    CHECK(taken(submission).size() == 3);
}

TEST_CASE("take_submission: a source file over 1 MiB is left out, and the note says why",
          "[intake]") {
    const TempFolder folder(0755);
    std::vector<ArchiveEntry> entries = complete_stages("");
    entries[1].contents = std::string((std::size_t{1} << 20) + 1, '/');
    const fs::path archive = folder.path() / "big.tar.gz";
    write_archive(archive, Format::tar_gz, entries);
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission = take_submission(archive, kManifests, work.path());
    CHECK(taken(submission).count("3_intersect/sphere.cpp") == 0);
    CHECK(submission.stages[1].missing == std::vector<std::string>{"sphere.cpp"});
    CHECK(notes(submission).find("over the 1 MiB a source file may be") != std::string::npos);
}

TEST_CASE("take_submission: links are never taken, and never reach outside the work folder",
          "[intake]") {
    const TempFolder folder(0755);
    std::vector<ArchiveEntry> entries = {
        {"stages/1_vectors/vectors.cpp", "", "/etc/passwd", ""},
        {"stages/3_intersect/sphere.cpp", "", "", "/etc/shadow"},
        {"stages/3_intersect/plane.cpp", "", "", "../../../../etc/hostname"}};
    const fs::path archive = folder.path() / "links.tar";
    write_archive(archive, Format::pax, entries);
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission = take_submission(archive, kManifests, work.path());
    CHECK(taken(submission).empty());
    CHECK(notes(submission).find("a link, not a file") != std::string::npos);
    for (const std::string& file : files_under(work.path())) {
        INFO(file);
        CHECK(!fs::is_symlink(work.path() / file));
    }
}

TEST_CASE(
    "take_submission: entry names with '..', absolute paths and bytes that are not UTF-8 "
    "name nothing on disk",
    "[intake]") {
    const TempFolder folder(0755);
    const std::vector<ArchiveEntry> entries = {
        {"../../../../tmp/raystep-escape/vectors.cpp", "// up", "", ""},
        {"/tmp/raystep-escape/sphere.cpp", "// absolute", "", ""},
        {"stages/3_intersect/\xff\xfe/plane.cpp", "// not UTF-8", "", ""}};
    const fs::path archive = folder.path() / "names.tar";
    write_archive(archive, Format::pax, entries);
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission = take_submission(archive, kManifests, work.path());
    CHECK(taken(submission).size() == 3);
    CHECK_FALSE(fs::exists("/tmp/raystep-escape"));
    for (const std::string& file : files_under(folder.path())) {
        INFO(file);
        CHECK((file == "names.tar" ||
               fs::path(folder.path() / file).string().rfind(work.path().string(), 0) == 0));
    }
}

TEST_CASE("take_submission: of two entries at one place, the last is taken, as unpacking leaves it",
          "[intake]") {
    const TempFolder folder(0755);
    for (const Format format : {Format::zip, Format::pax}) {
        // The second spelt as some tools write it: "./" first, a doubled slash.
        std::vector<ArchiveEntry> entries = complete_stages("");
        entries.push_back({"./stages//1_vectors/vectors.cpp", "// vectors, fixed", "", ""});
        const fs::path archive = folder.path() / "twice";
        fs::remove(archive);
        write_archive(archive, format, entries);
        const WorkFolder work(folder.path(), "work-", false);

        const Submission submission = take_submission(archive, kManifests, work.path());
        CHECK(taken(submission).at("1_vectors/vectors.cpp") == "// vectors, fixed");
        CHECK(taken(submission).at("3_intersect/sphere.cpp") == "// sphere");
        CHECK(notes(submission)
                  .find("vectors.cpp: 2 entries of that name; took the last of the 2 "
                        "at stages/1_vectors/vectors.cpp") != std::string::npos);
    }
}

TEST_CASE("take_submission: where the last entry at a place cannot be taken, no earlier one is",
          "[intake]") {
    const TempFolder folder(0755);
    std::vector<ArchiveEntry> entries = complete_stages("");
    entries.push_back({"stages/1_vectors/vectors.cpp", "", "", "/etc/passwd"});
    const fs::path archive = folder.path() / "replaced-by-a-link.tar";
    write_archive(archive, Format::pax, entries);
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission = take_submission(archive, kManifests, work.path());
    CHECK(taken(submission).count("1_vectors/vectors.cpp") == 0);
    CHECK(notes(submission).find("left out stages/1_vectors/vectors.cpp (a link, not a file)") !=
          std::string::npos);
}

TEST_CASE("take_submission: what unpacks past the budget is left out, and the note says why",
          "[intake]") {
    const TempFolder folder(0755);
    std::vector<ArchiveEntry> entries;
    for (int copy = 0; copy < 40; ++copy) {
        entries.push_back(
            {"copy" + std::to_string(copy) + "/vectors.cpp", std::string(1 << 20, 'v'), "", ""});
    }
    const fs::path archive = folder.path() / "copies.zip";
    write_archive(archive, Format::zip, entries);
    const WorkFolder work(folder.path(), "work-", false);

    IntakeBudget budget;
    budget.total = std::uintmax_t{4} << 20;
    const Submission submission = take_submission(archive, kManifests, work.path(), budget);
    CHECK(taken(submission).count("1_vectors/vectors.cpp") == 1);
    CHECK(notes(submission).find("past the 4 MiB a submission may unpack") != std::string::npos);
}

TEST_CASE(
    "take_submission: a file that is no archive, an empty one, and no file at all each say "
    "what they are",
    "[intake]") {
    const TempFolder folder(0755);
    const WorkFolder work(folder.path(), "work-", false);
    const fs::path text = folder.path() / "essay.zip";
    std::ofstream(text) << "This is my ray tracer. It works on my machine.\n";
    const fs::path empty = folder.path() / "empty.zip";
    std::ofstream{empty};
    const fs::path nothing = folder.path() / "missing.zip";

    const Submission not_archive = take_submission(text, kManifests, work.path());
    CHECK(not_archive.problem.find("not a folder, nor an archive") != std::string::npos);
    CHECK(taken(not_archive).empty());
    CHECK(not_archive.stages.size() == kManifests.size());
    CHECK_FALSE(take_submission(empty, kManifests, work.path()).problem.empty());
    CHECK(take_submission(nothing, kManifests, work.path()).problem == "it does not exist");
}

TEST_CASE("take_submission: a folder's files are taken, its links are not", "[intake]") {
    const TempFolder folder(0755);
    const fs::path root = folder.path() / "alice";
    fs::create_directories(root / "stages/3_intersect");
    fs::create_directories(root / "old");
    std::ofstream(root / "stages/3_intersect/sphere.cpp") << "// sphere";
    std::ofstream(root / "old/sphere.cpp") << "// an older sphere";
    std::ofstream(root / "plane.cpp") << "// plane";
    fs::create_symlink("/etc/passwd", root / "vectors.cpp");
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission = take_submission(root, kManifests, work.path());
    CHECK(taken(submission) ==
          std::map<std::string, std::string>{{"3_intersect/sphere.cpp", "// sphere"},
                                             {"3_intersect/plane.cpp", "// plane"}});
    CHECK(notes(submission).find("took stages/3_intersect/sphere.cpp") != std::string::npos);
}

TEST_CASE("submission_name: a safe folder name, whatever the submission is called", "[intake]") {
    CHECK(submission_name("/class/alice.zip") == "alice");
    CHECK(submission_name("/class/bob smith.tar.gz") == "bob_smith");
    CHECK(submission_name("/class/...zip") == "submission");
    CHECK(submission_name("/class/..") == "submission");
    CHECK(submission_name("/class/.hidden") == "hidden");
    CHECK(submission_name("/class/a\nb;rm -rf") == "a_b_rm_-rf");
    CHECK(submission_name("/class/\xc3\xa9l\xc3\xa8ve") == "__l__ve");
    CHECK(submission_name("/class/" + std::string(300, 'x')).size() == 100);
}

TEST_CASE("class_submissions: every entry but the output folder, each under a name of its own",
          "[intake]") {
    const TempFolder folder(0755);
    for (const char* name :
         {"alice.zip", "alice", "...zip", "..zip", "notes.txt", "grades.csv.zip"}) {
        std::ofstream(folder.path() / name) << "x";
    }
    fs::create_directories(folder.path() / "grades");
    const std::vector<ClassEntry> entries =
        class_submissions(folder.path(), folder.path() / "grades");
    std::vector<std::string> names;
    for (const ClassEntry& entry : entries)
        names.push_back(entry.name);
    CHECK(names == std::vector<std::string>{"submission", "submission-2", "alice", "alice-2",
                                            "grades.csv-2", "notes.txt"});
    for (const ClassEntry& entry : entries) {
        const fs::path reports = (folder.path() / "grades" / entry.name).lexically_normal();
        CHECK(reports.parent_path() == folder.path() / "grades");
    }
}

TEST_CASE("take_submission: a taken file's copy is readable by all, whatever its own mode",
          "[intake]") {
    const TempFolder folder(0755);
    const fs::path root = folder.path() / "carol";
    fs::create_directories(root / "stages/1_vectors");
    const fs::path file = root / "stages/1_vectors/vectors.cpp";
    std::ofstream(file) << "// vectors";
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                              fs::perms::others_read);
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission = take_submission(root, kManifests, work.path());
    REQUIRE(submission.stages[0].files.size() == 1);
    const fs::perms mode = fs::status(submission.stages[0].files[0]).permissions();
    CHECK((mode & fs::perms::others_read) == fs::perms::others_read);
}

TEST_CASE(
    "take_submission: a root grader reads a folder as a user of its own, so a private (0700) "
    "folder is refused with the command that opens it",
    "[intake]") {
    if (geteuid() != 0) {
        WARN("not root: the folder is read as the grader's own user, who may read it");
        return;
    }
    const TempFolder folder(0755);
    const fs::path root = folder.path() / "erin";
    fs::create_directories(root / "stages/1_vectors");
    std::ofstream(root / "stages/1_vectors/vectors.cpp") << "// vectors";
    fs::permissions(root / "stages", fs::perms::owner_all);
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission = take_submission(root, kManifests, work.path());
    CHECK(taken(submission).empty());
    CAPTURE(submission.problem);
    CHECK(submission.problem.find("chmod -R go+rX") != std::string::npos);
}

// A folder submission whose way to its files passes a link, where the link leads to the
// instructor's solutions. Whatever the link is, nothing is taken through it, and the problem names
// it.
TEST_CASE("take_submission: a link at any depth of a folder hands in nothing, and is named",
          "[intake]") {
    const TempFolder folder(0755);
    // What a link may reach: a copy of the repository's layout, solutions included
    const fs::path repository = folder.path() / "repository";
    for (const char* layer : {"solutions", "stages"}) {
        fs::create_directories(repository / layer / "3_intersect");
        std::ofstream(repository / layer / "3_intersect/sphere.cpp") << "// the reference sphere";
        std::ofstream(repository / layer / "3_intersect/plane.cpp") << "// the reference plane";
    }
    struct Layout {
        std::string name;
        std::string link;  ///< inside the submission
        fs::path target;
    };
    const std::string source = RAYSTEP_SOURCE_DIR;
    const std::vector<Layout> layouts = {
        {"a linked stages folder", "stages", repository / "solutions"},
        {"a linked stage folder", "stages/3_intersect", repository / "solutions/3_intersect"},
        {"a link in the middle of a path", "work/stages", repository / "solutions"},
        {"a link to the repository itself", "repo", repository},
        {"a link to the real repository", "raystep", source},
        {"a link to /proc/self/root", "root", "/proc/self/root"},
    };
    for (const Layout& layout : layouts) {
        CAPTURE(layout.name);
        const fs::path root = folder.path() / "mallory";
        fs::remove_all(root);
        fs::create_directories((root / layout.link).parent_path());
        if (layout.link != "stages") {
            fs::create_directories(root / "stages/1_vectors");
            std::ofstream(root / "stages/1_vectors/vectors.cpp") << "// vectors";
        }
        fs::create_directory_symlink(layout.target, root / layout.link);
        const WorkFolder work(folder.path(), "work-", false);

        const Submission submission = take_submission(root, kManifests, work.path());
        std::map<std::string, std::string> expected;
        if (layout.link != "stages") expected["1_vectors/vectors.cpp"] = "// vectors";
        CHECK(taken(submission) == expected);
        CAPTURE(submission.problem);
        CHECK(submission.problem.find(layout.link + " (a link to " + layout.target.string()) !=
              std::string::npos);
    }
}

TEST_CASE("take_submission: a working copy's 25,000 build products do not hide its sources",
          "[intake]") {
    const TempFolder folder(0755);
    const fs::path root = folder.path() / "dave";
    fs::create_directories(root / "stages/1_vectors");
    std::ofstream(root / "stages/1_vectors/vectors.cpp") << "// vectors";
    for (const char* tool_folder : {"build/deps", "aaa/deps"}) {
        fs::create_directories(root / tool_folder);
        for (int k = 0; k < 12500; ++k)
            std::ofstream(root / tool_folder / (std::to_string(k) + ".o"));
    }
    const WorkFolder work(folder.path(), "work-", false);

    const Submission submission = take_submission(root, kManifests, work.path());
    CHECK(taken(submission).count("1_vectors/vectors.cpp") == 1);
}
