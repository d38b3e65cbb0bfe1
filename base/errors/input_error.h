#pragma once

#include <stdexcept>
#include <string>

namespace raystep {

/// Bad input from a file the user gave us (a scene, a mesh, a case file): what() reads
/// `file:line: problem`, or `file: problem` when no single line is to blame (line 0).
/// Library code throws it; only main turns it into a message and an exit code.
class InputError : public std::runtime_error {
  public:
    InputError(std::string file, int line, std::string problem);

    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& problem() const { return problem_; }

  private:
    std::string file_;
    int line_;
    std::string problem_;
};

}  // namespace raystep
