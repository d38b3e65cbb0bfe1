// `raystep submit [-o FILE] [--force]`: packs the files the stages' manifests list into a zip, the
// one a student hands in (docs/student-README.md, "Hand in"). It is added through
// CommandRegistry, so main.cpp needs no line for it; both `raystep` and a student release's have
// it, since app/ is in the release.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/command_registry.h"
#include "app/submit/stored_zip.h"
#include "app/submit/submission_files.h"

namespace raystep {

namespace {

namespace fs = std::filesystem;

struct SubmitArguments {
    std::string output = "submission.zip";
    bool force = false;
};

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (!in && !in.eof()) throw std::runtime_error(path.string() + ": cannot be read");
    return bytes.str();
}

// "12345" -> "12,345", the sizes as a person reads them.
std::string grouped(std::uintmax_t value) {
    std::string digits = std::to_string(value);
    for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3)
        digits.insert(static_cast<std::size_t>(at), ",");
    return digits;
}

// The names, comma-separated; overloads share a name, and each is said once.
std::string names_said_once(const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0 && names[i] == names[i - 1]) continue;
        text += (text.empty() ? "" : ", ") + names[i];
    }
    return text;
}

// Writes beside the zip first and renames it into place, so that the zip is never found half
// written (a full disk, an interrupted run): it is the old one or the whole new one.
void write_atomically(const fs::path& zip, const std::string& bytes) {
    const fs::path partial = zip.string() + ".partial";
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    std::error_code error;
    if (out) fs::rename(partial, zip, error);
    if (!out || error) {
        std::error_code ignored;
        fs::remove(partial, ignored);
        throw std::runtime_error(zip.string() + ": cannot be written" +
                                 (error ? " (" + error.message() + ")" : std::string()));
    }
}

int run_submit(const SubmitArguments& arguments) {
    const fs::path zip = fs::absolute(arguments.output);
    if (fs::exists(zip) && !arguments.force) {
        throw std::runtime_error(zip.string() +
                                 " already exists: --force replaces it, -o writes another file");
    }
    if (!fs::is_directory(zip.parent_path()))
        throw std::runtime_error(zip.parent_path().string() + ": no such folder for the zip");
    const fs::path root = find_repository_root(fs::current_path());
    const std::vector<SubmissionFile> files = submission_files(root);

    std::printf("The files the stages' manifests list (%s/stages/*/manifest.txt):\n",
                root.string().c_str());
    int width = 0;
    for (const SubmissionFile& file : files)
        width = std::max(width, static_cast<int>(file.name.size()));
    std::vector<ZipEntry> entries;
    std::vector<const SubmissionFile*> stubbed;
    for (const SubmissionFile& file : files) {
        std::printf("  %-*s %9s bytes\n", width, file.name.c_str(), grouped(file.size).c_str());
        entries.push_back({file.name, read_bytes(file.path)});
        if (!file.stubs.empty()) stubbed.push_back(&file);
    }
    std::fflush(stdout);
    // A stub left in is the student's choice (a stage not done yet), never a reason to refuse: the
    // grader gives those functions no points, and says so.
    for (const SubmissionFile* file : stubbed) {
        std::fprintf(stderr,
                     "warning: %s: still stubs, which throw NotImplemented (RAYSTEP_TODO): %s\n",
                     file->name.c_str(), names_said_once(file->stubs).c_str());
    }
    std::fflush(stderr);

    const std::string bytes = stored_zip(entries);
    write_atomically(zip, bytes);
    std::printf(
        "wrote %s (%zu file%s, %s bytes)\nHand in that zip where your course says (README.md, "
        "\"Hand in\"); with GitHub Classroom, push your repository instead.\n",
        zip.string().c_str(), entries.size(), entries.size() == 1 ? "" : "s",
        grouped(bytes.size()).c_str());
    return 0;
}

AddedCommand add_submit(CLI::App& app) {
    auto arguments = std::make_shared<SubmitArguments>();
    CLI::App* command = app.add_subcommand(
        "submit",
        "Pack the files the stages' manifest.txt files list into a zip to hand in, and list them. "
        "Run it anywhere inside the repository. Exit 0 when written, 1 when not");
    command->add_option("-o,--output", arguments->output, "The zip to write")
        ->capture_default_str();
    command->add_flag("--force", arguments->force, "Replace the zip if it exists");
    return {command, [arguments] { return run_submit(*arguments); }};
}

const CommandRegistry::Registration kSubmitCommand(add_submit);

}  // namespace

}  // namespace raystep
