#include "base/errors/input_error.h"

namespace raystep {

namespace {

std::string located(const std::string& file, int line, const std::string& problem) {
    if (line <= 0) return file + ": " + problem;
    return file + ":" + std::to_string(line) + ": " + problem;
}

}  // namespace

InputError::InputError(std::string file, int line, std::string problem)
    : std::runtime_error(located(file, line, problem)),
      file_(std::move(file)),
      line_(line),
      problem_(std::move(problem)) {}

}  // namespace raystep
