// Stage 3 calls: one stage-3 function over a list of ray cases (questions only: the probe never
// sees the oracle's expectations), answered as core/check answers them for `raystep check`.

#include <algorithm>
#include <stdexcept>

#include "core/check/stage3_methods.h"
#include "grader/probe/call_table.h"

namespace raystep::probe {

void add_intersect_calls(CallTable& table) {
    table["stage3_cases"] = [](const Json& a) {
        const std::string name = a.at("method").get<std::string>();
        const std::vector<Stage3Method> methods = stage3_methods();
        const auto method = std::find_if(methods.begin(), methods.end(),
                                         [&](const Stage3Method& m) { return m.name == name; });
        if (method == methods.end()) throw std::invalid_argument("no stage-3 method " + name);
        Json answers = Json::array();
        for (const Json& question : a.at("cases")) {
            answers.push_back(case_answer(run_method(*method, case_question_from(question))));
        }
        return answers;
    };
}

}  // namespace raystep::probe
