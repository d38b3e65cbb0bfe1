#include "app/grade/data_judge.h"

#include <stdexcept>

namespace raystep::grade {

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
