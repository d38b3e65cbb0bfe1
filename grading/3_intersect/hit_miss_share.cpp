#include "grading/3_intersect/hit_miss_share.h"

#include <functional>
#include <utility>

namespace raystep::grade {

ProbeCase HitMissShare::counted(ProbeCase probe_case, CaseKind kind) {
    if (kind == CaseKind::either) return probe_case;
    const std::function<Judgement(const ProbeAnswer&)> judge = std::move(probe_case.judge);
    probe_case.judge = [judge, kind, tally = tally_](const ProbeAnswer& answer) {
        try {
            Judgement judgement = judge(answer);
            tally->count(kind, judgement.passed && judgement.not_implemented.empty());
            return judgement;
        } catch (...) {
            // An answer the judge cannot read is a wrong one (judge_answers counts it so)
            tally->count(kind, false);
            throw;
        }
    };
    return probe_case;
}

bool HitMissShare::score(CheckMeasure& measure) const {
    if (measure.grader_error || measure.outcome == Outcome::did_not_compile ||
        measure.outcome == Outcome::not_implemented || tally_->both_kinds_kept()) {
        return false;
    }
    measure.fraction = 0.0;
    measure.outcome = Outcome::failed;
    measure.summary += "; " + tally_->shortfall();
    return true;
}

}  // namespace raystep::grade
