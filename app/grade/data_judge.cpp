#include "app/grade/data_judge.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace raystep::grade {

Verdict verdict_right() {
    Verdict verdict;
    verdict.passed = true;
    return verdict;
}

Verdict verdict_wrong(std::string expected, std::string got) {
    Verdict verdict;
    verdict.expected = std::move(expected);
    verdict.got = std::move(got);
    return verdict;
}

Judge build_judge(const probe::Json& spec) {
    const std::string name = spec.at("judge").get<std::string>();
    for (const DataJudge& judge : JudgeRegistry::entries()) {
        if (judge.name == name) return judge.build(spec);
    }
    std::string known;
    for (const DataJudge& judge : JudgeRegistry::entries())
        known += (known.empty() ? "" : ", ") + judge.name;
    throw std::invalid_argument("no judge named '" + name + "' (this build has: " + known + ")");
}

}  // namespace raystep::grade
