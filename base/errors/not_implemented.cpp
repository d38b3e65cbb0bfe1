#include "base/errors/not_implemented.h"

namespace raystep {

namespace {

std::string message(int stage, const std::string& function, const std::string& section) {
    return "stage " + std::to_string(stage) + ": " + function +
           " is not implemented yet, see docs/stage" + std::to_string(stage) + ".md, section \"" +
           section + "\"";
}

}  // namespace

NotImplemented::NotImplemented(int stage, std::string function, std::string section)
    : std::logic_error(message(stage, function, section)),
      stage_(stage),
      function_(std::move(function)),
      section_(std::move(section)) {}

void throw_not_implemented(int stage, const char* function, const char* section) {
    throw NotImplemented(stage, function, section);
}

}  // namespace raystep
