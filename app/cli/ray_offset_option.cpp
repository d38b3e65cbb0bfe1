#include "app/cli/ray_offset_option.h"

#include <cstdio>
#include <string>

#include "app/cli/finite_number_check.h"

namespace raystep {

std::string RayOffsetArguments::command_line() const {
    if (rule.empty()) return "";
    std::string text = " --ray-offset " + rule;
    if (epsilon > 0.0) {
        char number[32];
        std::snprintf(number, sizeof number, "%.17g", epsilon);  // the same double back
        text += std::string(" --epsilon ") + number;
    }
    return text;
}

void add_ray_offset_options(CLI::App& command, RayOffsetArguments& arguments) {
    command
        .add_option("--ray-offset", arguments.rule,
                    "Where shadow and mirror rays start: error-bound (no epsilon), along-ray or "
                    "along-normal (with --epsilon). Default: the scene's rayoffset, else "
                    "error-bound")
        ->check(CLI::IsMember({"along-ray", "along-normal", "error-bound"}));
    command
        .add_option("--epsilon", arguments.epsilon,
                    "The offset distance of along-ray and along-normal")
        ->check(finite_number_check("EPSILON", "the offset distance must be a number above 0",
                                    [](double value) { return value > 0.0; }));
    // The two options make sense only together: checked once both are read, as a command-line
    // error (exit code 2), before any scene is loaded.
    command.parse_complete_callback([&arguments] {
        const bool has_epsilon = arguments.epsilon > 0.0;
        if (arguments.rule.empty()) {
            if (has_epsilon) {
                throw CLI::ValidationError("--epsilon",
                                           "needs --ray-offset along-ray or along-normal");
            }
            return;
        }
        const bool needs_epsilon = uses_epsilon(*parse_offset_rule(arguments.rule));
        if (needs_epsilon && !has_epsilon) {
            throw CLI::ValidationError("--ray-offset",
                                       arguments.rule + " needs --epsilon, the offset distance");
        }
        if (!needs_epsilon && has_epsilon) {
            throw CLI::ValidationError("--ray-offset",
                                       "error-bound takes no --epsilon: it needs no tuning");
        }
    });
}

void apply_ray_offset(const RayOffsetArguments& arguments, Scene& scene) {
    if (arguments.rule.empty()) return;
    scene.ray_offset = {*parse_offset_rule(arguments.rule), arguments.epsilon};
}

}  // namespace raystep
