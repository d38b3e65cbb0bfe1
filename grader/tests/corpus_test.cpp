// The grader against its corpus (grader/tests/submissions/README.md): the model submission, graded
// in a class, gets full marks; every mutant loses points in its own stage; every correct
// alternative gets full marks; every hostile submission ends in bounded time with a low score and
// a complete report, reads nothing secret and writes nothing outside its output folder.
//
// Each entry is graded by the real raystep-grade, as an instructor would run it, a few at a time.
// A mutant, alternative or hostile entry is a diff against the model: the submission is the
// model's files of the diff's stage, with the diff applied (git apply), graded on that stage.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <sys/wait.h>

#include <nlohmann/json.hpp>
#include "base/testing/catch.h"
#include "base/testing/command_run.h"

#include "grader/grade/check_definition.h"
#include "grader/grade/report_folders.h"
#include "grader/grade/report_json.h"
#include "grader/grade/stage_manifests.h"

namespace fs = std::filesystem;
using raystep::grade::CheckResult;
using raystep::grade::GradeReport;
using raystep::grade::Outcome;
using raystep::testing::file_text;
using raystep::testing::shell_word;

namespace {

const fs::path kSource = RAYSTEP_SOURCE_DIR;
const fs::path kCorpus = kSource / "grader/tests/submissions";
const fs::path kWork = RAYSTEP_CORPUS_WORK;
// What the write-outside-sandbox submission tries to leave everywhere.
const std::string kMark = "raystep-hostile-was-here";

// One graded entry: its report (absent when raystep-grade wrote none), how long grading took.
struct Graded {
    fs::path diff;
    int stage = 0;
    fs::path output;
    std::optional<GradeReport> report;
    double seconds = 0.0;
    std::string problem;  ///< why there is no report
};

// "4-bvh-skips-far-child.diff" is stage 4's, "10-roulette-without-division.diff" stage 10's: the
// number before the first hyphen.
int stage_of(const fs::path& diff) {
    const std::string name = diff.filename().string();
    return std::stoi(name.substr(0, name.find('-')));
}

std::vector<fs::path> diffs_in(const std::string& folder) {
    std::vector<fs::path> diffs;
    for (const fs::directory_entry& entry : fs::directory_iterator(kCorpus / folder)) {
        if (entry.path().extension() == ".diff") diffs.push_back(entry.path());
    }
    std::sort(diffs.begin(), diffs.end());
    return diffs;
}

// The eyes of every entry's render checks, drawn once when the test starts, as a batch draws one
// for its class (grader/grade/batch.h): a new eye in every run, and the reference's noisy renders
// from it made once for all the entries, in the shared cache's renders/eye-SEED
// (GradingContext::kept_renders), which is removed when the test ends, as a batch removes its
// cache: no later run looks from that eye.
class CorpusEye {
  public:
    CorpusEye() : seed_(raystep::grade::fresh_grade_seed()) {}
    ~CorpusEye() {
        std::error_code ignored;
        fs::remove_all(kWork / "cache" / "renders" / ("eye-" + std::to_string(seed_)), ignored);
    }
    CorpusEye(const CorpusEye&) = delete;
    CorpusEye& operator=(const CorpusEye&) = delete;

    std::uint64_t seed() const { return seed_; }

  private:
    std::uint64_t seed_;
};

std::uint64_t corpus_eye_seed() {
    static const CorpusEye eye;
    return eye.seed();
}

// Runs raystep-grade on `submission`; `arguments` narrow it (--stage N --no-speed). Every entry
// shares one --cache and one --eye-seed, as a class's submissions do in a batch: a mutant compiles
// the one file it changes, and the hostile entries meet the cache the others fill.
void grade(Graded& entry, const fs::path& submission, const std::string& arguments) {
    fs::remove_all(entry.output);
    fs::create_directories(entry.output.parent_path());
    const auto start = std::chrono::steady_clock::now();
    const std::string command =
        shell_word(RAYSTEP_GRADE_PROGRAM) + " submission " + shell_word(submission) + " -o " +
        shell_word(entry.output) + " --jobs 1 --cache " + shell_word(kWork / "cache") +
        " --eye-seed " + std::to_string(corpus_eye_seed()) + " " + arguments + " > " +
        shell_word(entry.output.string() + ".log") + " 2>&1";
    const int status = std::system(command.c_str());
    entry.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    try {
        entry.report = raystep::grade::report_from_json(
            nlohmann::json::parse(file_text(raystep::grade::finished_report_file(entry.output))));
    } catch (const std::exception& error) {
        entry.problem = "raystep-grade exited with " + std::to_string(status) +
                        " and no readable report.json (" + error.what() + "); its output is in " +
                        entry.output.string() + ".log";
    }
}

// The model's files of the diff's stage, the diff applied.
fs::path mutated_submission(const fs::path& diff, const fs::path& folder) {
    fs::remove_all(folder);
    const int stage = stage_of(diff);
    for (const raystep::grade::StageManifest& manifest :
         raystep::grade::read_stage_manifests(kSource)) {
        if (manifest.number != stage) continue;
        fs::create_directories(folder / "stages");
        fs::copy(kCorpus / "model/stages" / manifest.folder, folder / "stages" / manifest.folder,
                 fs::copy_options::recursive);
    }
    const std::string apply = "cd " + shell_word(folder) + " && git apply -p1 " + shell_word(diff);
    if (std::system(apply.c_str()) != 0)
        throw std::runtime_error("git apply failed for " + diff.string());
    return folder;
}

// Grades every diff of a folder of the corpus on its own stage, a few at a time.
std::vector<Graded> grade_corpus(const std::string& folder) {
    const std::vector<fs::path> diffs = diffs_in(folder);
    std::vector<Graded> graded(diffs.size());
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t k = next++; k < diffs.size(); k = next++) {
            Graded& entry = graded[k];
            entry.diff = diffs[k];
            entry.stage = stage_of(diffs[k]);
            const fs::path base = kWork / folder / diffs[k].stem();
            entry.output = base / "report";
            try {
                const fs::path submission = mutated_submission(diffs[k], base / "submission");
                grade(entry, submission, "--stage " + std::to_string(entry.stage) + " --no-speed");
            } catch (const std::exception& error) {
                entry.problem = error.what();
            }
        }
    };
    // Grading is mostly compiling and waiting on probes: one more than the processors.
    std::vector<std::thread> workers(std::max(2u, std::thread::hardware_concurrency()) + 1);
    for (std::thread& worker : workers)
        worker = std::thread(work);
    for (std::thread& worker : workers)
        worker.join();
    return graded;
}

std::pair<double, double> stage_score(const GradeReport& report, int stage) {
    return report.stage_scores().at(static_cast<std::size_t>(stage));
}

std::string describe(const Graded& entry) {
    std::string text = entry.diff.filename().string();
    if (!entry.report) return text + ": " + entry.problem;
    const auto [score, max] = stage_score(*entry.report, entry.stage);
    text += ": stage " + std::to_string(entry.stage) + " " + std::to_string(score) + " / " +
            std::to_string(max) + " in " + std::to_string(entry.seconds) + " s";
    for (const CheckResult& check : entry.report->checks) {
        text += "\n  " + check.id + " " + std::to_string(check.score) + "/" +
                std::to_string(check.max_score) + ": " + check.summary;
    }
    return text;
}

// The share of its stage that a mutant's header promises it loses, from a comment line such as
// "# Loses at least 10% of its stage." above the diff: the classes of bug an issue named as
// costing too little (docs/measurements/check-power.md). nullopt where the header promises none.
std::optional<double> promised_loss(const fs::path& diff) {
    std::ifstream file(diff);
    const std::string marker = "# Loses at least ";
    for (std::string line; std::getline(file, line) && line.rfind("#", 0) == 0;) {
        if (line.rfind(marker, 0) != 0) continue;
        return std::stod(line.substr(marker.size())) / 100.0;
    }
    return std::nullopt;
}

// What a mutant's header promises a check of its stage says, from a comment line such as
// "# Says: its timed runs took more than" above the diff: where the grade's reason for failing it
// is the point (a defence the mutant attacks). nullopt where the header promises none.
std::optional<std::string> promised_saying(const fs::path& diff) {
    std::ifstream file(diff);
    const std::string marker = "# Says: ";
    for (std::string line; std::getline(file, line) && line.rfind("#", 0) == 0;) {
        if (line.rfind(marker, 0) == 0) return line.substr(marker.size());
    }
    return std::nullopt;
}

// The files under `folder`, by path relative to it, in order.
std::vector<std::string> files_under(const fs::path& folder) {
    std::vector<std::string> files;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder)) {
        files.push_back(fs::relative(entry.path(), folder).string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

const CheckResult* find_check(const GradeReport& report, const std::string& id) {
    for (const CheckResult& check : report.checks) {
        if (check.id == id) return &check;
    }
    return nullptr;
}

// Every folder above `output`, and the other places a submission might try to write.
std::vector<fs::path> places_outside(const fs::path& output) {
    std::vector<fs::path> places = {"/tmp", "/autograder", "/autograder/results", kSource,
                                    fs::current_path()};
    if (const char* home = std::getenv("HOME")) places.push_back(home);
    for (fs::path p = output; p.has_relative_path(); p = p.parent_path())
        places.push_back(p.parent_path());
    return places;
}

// The student stubs of stages/ themselves, every stage, as a submission; `appended` added to the
// end of the first file of each stage's manifest.
fs::path stub_submission(const fs::path& folder, const std::string& appended) {
    fs::remove_all(folder);
    for (const raystep::grade::StageManifest& manifest :
         raystep::grade::read_stage_manifests(kSource)) {
        const fs::path stage = folder / "stages" / manifest.folder;
        fs::create_directories(stage);
        for (const std::string& file : manifest.files) {
            fs::copy_file(kSource / "stages" / manifest.folder / file, stage / file);
        }
        std::ofstream(stage / manifest.files.front(), std::ios::app) << "\n" << appended;
    }
    return folder;
}

// Every check of a full grade (speed included) earns nothing and none passes: each is "not
// implemented", which is what a submission of stubs is, however it tries to borrow an answer.
void require_honest_zero(const Graded& stubs) {
    INFO(describe(stubs));
    REQUIRE(stubs.report);
    REQUIRE(stubs.report->checks.size() > 40);
    for (const CheckResult& check : stubs.report->checks) {
        INFO(check.id << ": " << raystep::grade::outcome_name(check.outcome) << ", "
                      << check.summary);
        CHECK(check.score == 0.0);
        CHECK(check.outcome == Outcome::not_implemented);
    }
    CHECK(stubs.report->score() == 0.0);
}

// The model's report: every check at full marks, and each with points passed, in every report
// (Gradescope shows a test's status in colour: no test at full points may read "failed").
void require_full_marks(const GradeReport& report, const fs::path& output) {
    REQUIRE(report.checks.size() > 40);
    for (const CheckResult& check : report.checks) {
        // Full marks, which is not always every case passed: the lecture's triangle tests lose a
        // few slivers by design, and the rubric allows for it.
        INFO(check.id << ": " << check.summary);
        CHECK(check.score == check.max_score);
        if (check.max_score > 0) CHECK(check.outcome == Outcome::passed);
    }
    const nlohmann::json results = nlohmann::json::parse(
        file_text(raystep::grade::instructor_folder(output) / "results.json"));
    for (const nlohmann::json& test : results.at("tests")) {
        INFO(test.value("name", ""));
        if (test.at("max_score").get<double>() > 0 &&
            test.at("score").get<double>() == test.at("max_score").get<double>()) {
            CHECK(test.at("status") == "passed");
        }
    }
}

// `raystep-grade batch ARGUMENTS` run in `root`, its output in root/LOG: the exit code.
int run_batch(const fs::path& root, const std::string& arguments, const std::string& log) {
    const std::string command = "cd " + shell_word(root) + " && " +
                                shell_word(RAYSTEP_GRADE_PROGRAM) + " batch " + arguments + " > " +
                                log + " 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A class's grades.csv, each row without its last field, the seconds it took.
std::vector<std::string> rows_without_seconds(const fs::path& csv) {
    std::vector<std::string> rows;
    std::ifstream in(csv);
    for (std::string line; std::getline(in, line);)
        rows.push_back(line.substr(0, line.rfind(',')));
    return rows;
}

}  // namespace

TEST_CASE("a submission of only the stubs scores 0 on every check and passes none", "[corpus]") {
    Graded stubs;
    stubs.output = kWork / "stubs/report";
    const fs::path submission = stub_submission(kWork / "stubs/submission", "");
    grade(stubs, submission, "");
    require_honest_zero(stubs);
}

TEST_CASE(
    "a submission of only the stubs that execs a sibling probe to borrow the reference "
    "scores 0 on every check",
    "[corpus]") {
    Graded stubs;
    stubs.output = kWork / "stubs-exec-sibling-probe/report";
    const fs::path submission =
        stub_submission(kWork / "stubs-exec-sibling-probe/submission",
                        file_text(kCorpus / "hostile/stubs-exec-sibling-probe.cpp"));
    grade(stubs, submission, "");
    require_honest_zero(stubs);
}

TEST_CASE(
    "a submission that sleeps in every call ends when the grade's checks run out of time, each "
    "check not started by then timed out with no points",
    "[corpus]") {
    Graded entry;
    entry.output = kWork / "checks-time-limit/report";
    const fs::path submission = mutated_submission(kCorpus / "hostile/1-sleep-forever.diff",
                                                   kWork / "checks-time-limit/submission");
    grade(entry, submission, "--stage 1 --no-speed --checks-time-limit 5");
    INFO(describe(entry));
    REQUIRE(entry.report);
    // The first check waits out its own 20 s past the grade's 5; the others do not start.
    CHECK(entry.seconds < 60.0);
    std::size_t not_run = 0;
    for (const CheckResult& check : entry.report->checks) {
        INFO(check.id << ": " << check.summary);
        CHECK(check.outcome == Outcome::timed_out);
        CHECK(check.score == 0.0);
        if (check.summary.rfind("not run: the grade's checks had taken the 5 s", 0) == 0) ++not_run;
    }
    CHECK(not_run + 1 == entry.report->checks.size());
}

TEST_CASE("every mutant loses points in its own stage", "[corpus]") {
    const std::vector<Graded> graded = grade_corpus("mutants");
    REQUIRE(graded.size() >= 30);
    std::vector<int> stages;
    for (const Graded& entry : graded) {
        INFO(describe(entry));
        REQUIRE(entry.report);
        const auto [score, max] = stage_score(*entry.report, entry.stage);
        CHECK(max > 0.0);
        CHECK(score < max);
        if (const std::optional<double> share = promised_loss(entry.diff)) {
            INFO("its header promises it loses at least " << 100.0 * *share << "% of its stage");
            CHECK(max - score >= *share * max - 1e-9);
        }
        if (const std::optional<std::string> saying = promised_saying(entry.diff)) {
            INFO("its header promises a check of its stage says \"" << *saying << "\"");
            CHECK(std::any_of(entry.report->checks.begin(), entry.report->checks.end(),
                              [&](const CheckResult& check) {
                                  return check.stage == entry.stage &&
                                         check.summary.find(*saying) != std::string::npos;
                              }));
        }
        stages.push_back(entry.stage);
    }
    for (int stage = 1; stage <= raystep::grade::kLastStage; ++stage) {
        INFO("stage " << stage);
        CHECK(std::count(stages.begin(), stages.end(), stage) >= 2);
    }
}

TEST_CASE("every correct alternative gets full marks in its stage", "[corpus]") {
    const std::vector<Graded> graded = grade_corpus("alternatives");
    REQUIRE(graded.size() >= 5);
    for (const Graded& entry : graded) {
        INFO(describe(entry));
        REQUIRE(entry.report);
        const auto [score, max] = stage_score(*entry.report, entry.stage);
        CHECK(max > 0.0);
        CHECK(score == max);
    }
}

TEST_CASE(
    "every hostile submission ends in bounded time with a low score, a complete report, "
    "and nothing read or written outside its sandbox",
    "[corpus]") {
    for (const fs::path& diff : diffs_in("hostile")) {
        for (const fs::path& place : places_outside(kWork / "hostile" / diff.stem() / "report")) {
            std::error_code ignored;
            fs::remove(place / kMark, ignored);
        }
    }
    const std::vector<Graded> graded = grade_corpus("hostile");
    REQUIRE(graded.size() >= 10);
    // Lines of the reference solution, the hidden checks and the rubric: none may reach a report.
    const std::vector<std::string> secrets = {
        "Stage 1 reference solution",
        "the contract's edge cases a student's own tests may not reach",
        "The rubric raystep-grade scores by"};
    for (const Graded& entry : graded) {
        INFO(describe(entry));
        REQUIRE(entry.report);
        // Each check's probe runs end within their limits (20 s of processor, 40 s of wall
        // clock): three checks, one after another, and the build.
        CHECK(entry.seconds < 150.0);
        // dot is in the first case of the unit and oracle checks: both must fail.
        for (const std::string id : {"stage1.unit", "stage1.oracle"}) {
            const CheckResult* check = find_check(*entry.report, id);
            REQUIRE(check);
            INFO(id << ": " << check->summary);
            CHECK(check->outcome != Outcome::passed);
            CHECK(check->score < check->max_score);
        }
        // A complete report: every file, and the Gradescope score is the grader's own.
        const fs::path student = raystep::grade::student_folder(entry.output);
        const fs::path instructor = raystep::grade::instructor_folder(entry.output);
        for (const fs::path& file : {student / "index.html", student / "results.json",
                                     student / "junit.xml", instructor / "results.json",
                                     instructor / "prairielearn.json", instructor / "junit.xml",
                                     instructor / "instructor.html", instructor / "report.json"}) {
            INFO(file);
            CHECK(fs::is_regular_file(file));
        }
        const nlohmann::json results =
            nlohmann::json::parse(file_text(instructor / "results.json"));
        CHECK(results.at("score").get<double>() == Approx(entry.report->score()));
        const std::string everything =
            file_text(instructor / "report.json") + file_text(instructor / "instructor.html");
        for (const std::string& secret : secrets) {
            INFO("the report holds \"" << secret << "\"");
            CHECK(everything.find(secret) == std::string::npos);
        }
        for (const fs::path& place : places_outside(entry.output)) {
            INFO("written outside the output folder: " << (place / kMark));
            CHECK_FALSE(fs::exists(place / kMark));
        }
    }
}

TEST_CASE(
    "a class of odd submissions and the model, graded into a relative -o under a private folder, "
    "gets a complete report each, all inside -o, and the model full marks on every check",
    "[corpus]") {
    const fs::path root = kWork / "class";
    fs::remove_all(root);
    const fs::path class_folder = root / "submissions";
    const fs::path model_stage1 = kCorpus / "model/stages/1_vectors";
    fs::create_directories(class_folder / "empty");
    // Archives of the model, whole and stage 1 alone, made by cmake -E tar as a student's zip
    // tool would.
    const auto pack = [&](const fs::path& from, const std::string& what, const fs::path& archive,
                          const std::string& format) {
        const std::string command = "cd " + shell_word(from) + " && " + shell_word(CMAKE_COMMAND) +
                                    " -E tar cf " + shell_word(archive) + " --format=" + format +
                                    " " + what;
        REQUIRE(std::system(command.c_str()) == 0);
    };
    pack(kCorpus / "model", "stages", class_folder / "model.zip", "zip");
    const fs::path stage1 = root / "stage1";
    fs::create_directories(stage1 / "stages");
    fs::copy(model_stage1, stage1 / "stages/1_vectors");
    pack(stage1, "stages", class_folder / "...zip", "zip");
    pack(stage1, "stages", class_folder / "tar-named.zip", "gnutar");
    // Stage 1 with a line that does not compile at its end.
    fs::copy(stage1, class_folder / "broken", fs::copy_options::recursive);
    std::ofstream(class_folder / "broken/stages/1_vectors/vectors.cpp", std::ios::app)
        << "int broken(\n";
    std::ofstream(class_folder / "essay.zip") << "My ray tracer is in my other folder.\n";
    // A working copy with a build product of 20 MiB beside the sources.
    fs::create_directories(stage1 / "build");
    std::ofstream(stage1 / "build/raystep", std::ios::binary)
        << std::string(std::size_t{20} << 20, '\1');
    pack(stage1, "stages build", class_folder / "with-build.zip", "zip");
    const std::vector<std::string> class_before = files_under(class_folder);

    // The grader's folder: private, as mktemp -d and many home folders make them; -o relative.
    const fs::path home = root / "home";
    fs::create_directories(home);
    fs::permissions(home, fs::perms::owner_all);
    const std::string command = "cd " + shell_word(home) + " && " +
                                shell_word(RAYSTEP_GRADE_PROGRAM) +
                                " batch ../submissions -o grades --jobs 2 > ../batch.log 2>&1";
    const int status = std::system(command.c_str());
    INFO(file_text(root / "batch.log"));
    CHECK(status == 0);

    const std::map<std::string, std::string> expected = {
        {"model", "model.zip"}, {"submission", "...zip"}, {"tar-named", "tar-named.zip"},
        {"essay", "essay.zip"}, {"empty", "empty"},       {"with-build", "with-build.zip"},
        {"broken", "broken"}};
    std::map<std::string, GradeReport> reports;
    for (const auto& [name, entry] : expected) {
        INFO(name << " from " << entry);
        const fs::path report = raystep::grade::finished_report_file(home / "grades" / name);
        REQUIRE(fs::is_regular_file(report));
        reports[name] = raystep::grade::report_from_json(nlohmann::json::parse(file_text(report)));
    }
    // The model, every stage with speed, graded as a class is: full marks on every check.
    CHECK(reports["model"].intake_problem.empty());
    require_full_marks(reports["model"], home / "grades" / "model");
    for (const std::string name : {"submission", "tar-named", "with-build"}) {
        INFO(name);
        CHECK(stage_score(reports[name], 1).first == stage_score(reports[name], 1).second);
        CHECK(reports[name].intake_problem.empty());
    }
    CHECK(reports["essay"].intake_problem.find("nor an archive") != std::string::npos);
    CHECK_FALSE(reports["empty"].intake_problem.empty());
    CHECK(reports["essay"].score() == 0.0);
    // The compiler's message names the file as the student's repository does, not the work
    // folder it was compiled in.
    for (const CheckResult& check : reports["broken"].checks) {
        if (check.stage != 1) continue;
        INFO(check.id << ": " << check.details);
        CHECK(check.outcome == Outcome::did_not_compile);
        CHECK(check.details.rfind("stages/1_vectors/vectors.cpp:", 0) == 0);
        CHECK(check.details.find("work-") == std::string::npos);
    }

    // Nothing but grades/ in the grader's folder, nothing changed among the submissions, and no
    // work folder left.
    std::vector<std::string> in_home;
    for (const fs::directory_entry& entry : fs::directory_iterator(home))
        in_home.push_back(entry.path().filename());
    CHECK(in_home == std::vector<std::string>{"grades"});
    CHECK(files_under(class_folder) == class_before);
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(home / "grades")) {
        INFO(entry.path());
        CHECK(entry.path().filename().string().rfind("work-", 0) != 0);
    }
    const std::string csv = file_text(home / "grades/grades.csv");
    CHECK(std::count(csv.begin(), csv.end(), '\n') == 1 + static_cast<long>(expected.size()));
}

TEST_CASE(
    "a class graded as three shards and merged has one row per student as one batch does, and a "
    "missing shard and a shard graded with other checks are warned of",
    "[corpus]") {
    const fs::path root = kWork / "shards";
    fs::remove_all(root);
    const fs::path class_folder = root / "submissions";
    // Submissions that need no build, so that the test is about sharding, not grading.
    for (const std::string name : {"ana", "ben", "chloe", "dev", "eli"})
        fs::create_directories(class_folder / name);
    std::ofstream(class_folder / "essay.zip") << "My ray tracer is in my other folder.\n";
    const auto run = [&](const std::string& arguments, const std::string& log) {
        return run_batch(root, arguments, log);
    };
    REQUIRE(run("submissions -o whole --no-speed", "whole.log") == 0);
    for (int shard = 1; shard <= 3; ++shard) {
        const std::string i = std::to_string(shard);
        REQUIRE(run("submissions -o shard" + i + " --no-speed --shard " + i + "/3",
                    "shard" + i + ".log") == 0);
    }
    // Each shard graded two of the six, round robin: shard 1 the first and fourth by name.
    const nlohmann::json first = nlohmann::json::parse(file_text(root / "shard1/shard.json"));
    CHECK(first.at("students") == nlohmann::json({"ana", "dev"}));

    const int merged = run("--merge shard1 shard2 shard3 -o merged", "merged.log");
    INFO(file_text(root / "merged.log"));
    CHECK(merged == 0);
    // The same rows as one batch's, but for the seconds each took.
    const std::vector<std::string> whole = rows_without_seconds(root / "whole/grades.csv");
    CHECK(whole.size() == 7);
    CHECK(rows_without_seconds(root / "merged/grades.csv") == whole);

    CHECK(run("--merge shard1 shard3 -o partial", "partial.log") == 1);
    CHECK_THAT(file_text(root / "partial.log"),
               Catch::Matchers::Contains("shard 2/3 is missing: its students are not in"));

    REQUIRE(run("submissions -o shard2-speed --shard 2/3", "speed.log") == 0);
    CHECK(run("--merge shard1 shard2-speed shard3 -o mixed", "mixed.log") == 1);
    CHECK_THAT(file_text(root / "mixed.log"),
               Catch::Matchers::Contains("was graded with other checks or points than ana"));
}

TEST_CASE(
    "a class graded several submissions at a time, speed checks in a second pass, gets one "
    "submission at a time's grades, each report's checks in the grader's order",
    "[corpus]") {
    const fs::path root = kWork / "parallel-batch";
    fs::remove_all(root);
    const fs::path class_folder = root / "submissions";
    // Submissions that need no build: every check, speed ones too, ends at once.
    for (const std::string name : {"ana", "ben", "chloe", "dev"})
        fs::create_directories(class_folder / name);
    std::ofstream(class_folder / "essay.zip") << "My ray tracer is in my other folder.\n";
    const auto run = [&](const std::string& arguments, const std::string& log) {
        return run_batch(root, arguments, log);
    };
    REQUIRE(run("submissions -o one --jobs 1", "one.log") == 0);
    REQUIRE(run("submissions -o three --jobs 3", "three.log") == 0);
    CHECK(rows_without_seconds(root / "one/grades.csv").size() == 6);
    CHECK(rows_without_seconds(root / "three/grades.csv") ==
          rows_without_seconds(root / "one/grades.csv"));
    const auto report_order = [&](const std::string& folder) {
        const nlohmann::json report =
            nlohmann::json::parse(file_text(root / folder / "ben" / "instructor" / "report.json"));
        std::vector<std::string> ids;
        for (const nlohmann::json& check : report.at("checks"))
            ids.push_back(check.at("id").get<std::string>());
        return ids;
    };
    // The grader's order: a submission graded on its own, every check in one pass.
    const std::string single = "cd " + shell_word(root) + " && " +
                               shell_word(RAYSTEP_GRADE_PROGRAM) +
                               " submission submissions/ben -o single/ben > single.log 2>&1";
    REQUIRE(std::system(single.c_str()) == 0);
    const std::vector<std::string> grader_order = report_order("single");
    CHECK(grader_order.size() > 40);
    CHECK(report_order("three") == grader_order);
    CHECK(report_order("one") == grader_order);

    // A batch stopped between its passes: the reports lack their speed checks, and a second run
    // adds just those.
    REQUIRE(run("submissions -o first-pass --no-speed", "first-pass.log") == 0);
    fs::copy(root / "first-pass", root / "resumed", fs::copy_options::recursive);
    REQUIRE(run("submissions -o resumed --jobs 2", "resumed.log") == 0);
    CHECK_THAT(file_text(root / "resumed.log"),
               Catch::Matchers::Contains("graded 5 submissions, 0 already graded before"));
    CHECK(report_order("resumed") == grader_order);
    CHECK(rows_without_seconds(root / "resumed/grades.csv") ==
          rows_without_seconds(root / "one/grades.csv"));
    REQUIRE(run("submissions -o resumed --jobs 2", "again.log") == 0);
    CHECK_THAT(file_text(root / "again.log"),
               Catch::Matchers::Contains("graded 0 submissions, 5 already graded before"));
}
