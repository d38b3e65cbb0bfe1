#include "app/cli/finite_number_check.h"

#include <cmath>
#include <cstdlib>
#include <utility>

namespace raystep {

CLI::Validator finite_number_check(std::string name, std::string problem,
                                   std::function<bool(double)> accept) {
    return CLI::Validator(
        [problem = std::move(problem), accept = std::move(accept)](std::string& text) {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (!text.empty() && *end == '\0' && std::isfinite(value) && (!accept || accept(value)))
                return std::string();
            return problem + ", not '" + text + "'";
        },
        std::move(name));
}

}  // namespace raystep
