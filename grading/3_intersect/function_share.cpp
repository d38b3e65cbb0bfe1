#include "grading/3_intersect/function_share.h"

#include <algorithm>

namespace raystep::grade {

namespace {

void add_once(std::vector<std::string>& names, const std::string& name) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

}  // namespace

ProbeCase FunctionShare::counted(ProbeCase probe_case, const std::string& function) {
    const std::function<Judgement(const ProbeAnswer&)> judge = std::move(probe_case.judge);
    probe_case.judge = [judge, function, tally = tally_](const ProbeAnswer& answer) {
        add_once(tally->asked, function);
        try {
            Judgement judgement = judge(answer);
            if (!judgement.passed || !judgement.not_implemented.empty())
                add_once(tally->broken, function);
            return judgement;
        } catch (...) {
            // An answer the judge cannot read is a wrong one (judge_answers counts it so)
            add_once(tally->broken, function);
            throw;
        }
    };
    return probe_case;
}

void FunctionShare::score(CheckMeasure& measure) const {
    if (tally_->asked.empty() || measure.outcome == Outcome::did_not_compile) return;
    const std::size_t kept = tally_->asked.size() - tally_->broken.size();
    measure.fraction = static_cast<double>(kept) / static_cast<double>(tally_->asked.size());
    measure.metrics["functions"] = static_cast<double>(tally_->asked.size());
    measure.metrics["functions keeping it"] = static_cast<double>(kept);
    if (tally_->broken.empty()) {
        measure.summary += "; every function asked keeps it";
        return;
    }
    std::string names;
    for (const std::string& name : tally_->broken)
        names += (names.empty() ? "" : ", ") + name;
    measure.summary += "; broken in " + names + " (" + std::to_string(kept) + " of " +
                       std::to_string(tally_->asked.size()) + " functions keep it)";
}

}  // namespace raystep::grade
