#pragma once

#include <string>
#include <utility>
#include <vector>

#include "grader/grade/check_definition.h"

namespace raystep::grade::hand_made {

// Cases and sessions made by hand, for the tests of how the grader judges answers
// (judge_answers_test.cpp, function_share_test.cpp).

/// A case that passes when the answer is the number 1.
inline ProbeCase wants_one(const std::string& name) {
    return {name,
            {"dot", {}},
            [](const ProbeAnswer& answer) {
                if (answer.kind != ProbeAnswer::Kind::result) return wrong("1", "");
                return answer.value == 1.0 ? right() : wrong("1", answer.value.dump());
            },
            name + "({1, 0, 0}, {1, 0, 0})"};
}

/// A probe session that answered `answers`, in order.
inline ProbeSession session(std::vector<ProbeAnswer> answers) {
    ProbeSession made;
    made.answers = std::move(answers);
    return made;
}

}  // namespace raystep::grade::hand_made
