#pragma once

#include <stdexcept>
#include <string>

namespace raystep {

/// Thrown by every student stub: names the stage, the function and the handout section, so a
/// test, a render or the grader can say exactly what is missing.
class NotImplemented : public std::logic_error {
  public:
    NotImplemented(int stage, std::string function, std::string section);

    int stage() const { return stage_; }
    const std::string& function() const { return function_; }
    const std::string& section() const { return section_; }

  private:
    int stage_;
    std::string function_;
    std::string section_;
};

/// Throws NotImplemented; the macro below is how stubs call it.
[[noreturn]] void throw_not_implemented(int stage, const char* function, const char* section);

}  // namespace raystep

/// Ends a student stub: `RAYSTEP_TODO(3, "intersect_sphere", "Ray-sphere");` throws
/// `stage 3: intersect_sphere is not implemented yet, see docs/stage3.md, section "Ray-sphere"`.
/// It never returns, so nothing (no plausible-looking wrong value) follows it.
#define RAYSTEP_TODO(stage, function, section) \
    ::raystep::throw_not_implemented(stage, function, section)
