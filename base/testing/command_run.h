#pragma once

// A program run as a user runs it, from a shell in a folder: its exit code and what it printed,
// for the tests of the commands (`raystep`, `raystep bench`) and of the scripts. Instructor-side
// tests only: a POSIX shell quotes the words.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#if !defined(_WIN32)
#include <sys/wait.h>
#endif

#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"

namespace raystep::testing {

struct CommandRun {
    int exit_code = -1;  ///< 128 + the signal's number where a signal ended it
    std::string out;     ///< what it wrote on stdout
    std::string err;     ///< what it wrote on stderr

    /// stdout, then stderr: what a terminal shows when one stream is written after the other.
    std::string output() const { return out + err; }
};

inline std::string shell_word(const std::string& word) {
    std::string quoted = "'";
    for (const char c : word)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

inline std::string file_text(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

/// Runs `words` (the program first) in `folder`, with `environment` (NAME=value settings) added;
/// its two streams go to files of a scratch folder of their own, so that `folder` gains nothing
/// else.
inline CommandRun run_command(const std::vector<std::string>& words,
                              const std::filesystem::path& folder,
                              const std::vector<std::string>& environment = {}) {
    std::string command = "cd " + shell_word(folder.string()) + " &&";
    for (const std::string& setting : environment) {
        const std::size_t equals = setting.find('=');
        command += " " + setting.substr(0, equals + 1) + shell_word(setting.substr(equals + 1));
    }
    for (const std::string& word : words)
        command += " " + shell_word(word);
    const ScratchFolder streams("streams");
    const std::filesystem::path out = streams.path() / "stdout";
    const std::filesystem::path err = streams.path() / "stderr";
    command += " > " + shell_word(out.string()) + " 2> " + shell_word(err.string());
    const int status = std::system(command.c_str());
    CommandRun run;
#if defined(_WIN32)
    run.exit_code = status;
#else
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
#endif
    run.out = file_text(out);
    run.err = file_text(err);
    return run;
}

/// Matches an output holding each pattern (an ECMAScript regular expression, `.` within a line)
/// after the one before it: {"a", "b"} as CMake's `a.*b`, across lines. `^` in the first pattern
/// is the output's first character (in a later one it matches nothing), `$` its last.
class PrintsInOrder : public MatcherBase<std::string> {
  public:
    explicit PrintsInOrder(std::vector<std::string> patterns) : patterns_(std::move(patterns)) {}

    bool match(const std::string& output) const override {
        auto from = output.cbegin();
        auto flags = std::regex_constants::match_default;
        for (const std::string& pattern : patterns_) {
            std::smatch found;
            if (!std::regex_search(from, output.cend(), found, std::regex(pattern), flags))
                return false;
            from = found[0].second;
            // Where the last pattern ended is no start of the output.
            flags = std::regex_constants::match_not_bol;
        }
        return true;
    }

    std::string describe() const override {
        std::string text = "prints, in this order:";
        for (const std::string& pattern : patterns_)
            text += "\n  " + pattern;
        return text;
    }

  private:
    std::vector<std::string> patterns_;
};

/// A run judged as a user judges it: the exit code must be `exit_code`, and the output must print
/// `patterns` in order; a failure shows the whole output.
inline void check_run(const CommandRun& run, int exit_code, std::vector<std::string> patterns) {
    INFO(run.output());
    CHECK(run.exit_code == exit_code);
    CHECK_THAT(run.output(), PrintsInOrder(std::move(patterns)));
}

/// `words` (the program first) run in a scratch folder of its own, judged by check_run.
inline void check_command(const std::vector<std::string>& words, int exit_code,
                          std::vector<std::string> patterns) {
    const ScratchFolder folder("command");
    check_run(run_command(words, folder.path()), exit_code, std::move(patterns));
}

}  // namespace raystep::testing
