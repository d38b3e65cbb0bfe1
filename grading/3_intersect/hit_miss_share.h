#pragma once

#include <memory>

#include "grader/grade/check_definition.h"
#include "grading/3_intersect/case_file_judges.h"

namespace raystep::grade {

/// The probe's side of a function's case check scored as case_file_judges.h scores the public
/// cases: by its share of the cases right, but nothing unless it gets at least
/// kLeastShareOfEachKind of the cases that must hit and of those that must miss right.
class HitMissShare {
  public:
    /// The case, its judge now also counting it among the hits or the misses asked and right.
    ProbeCase counted(ProbeCase probe_case, CaseKind kind);

    /// Makes the measure's fraction 0, failed, and says why in its summary, where fewer than
    /// kLeastShareOfEachKind of either kind were right; true then. A measure that did not
    /// compile or met a stub is left as it is.
    bool score(CheckMeasure& measure) const;

  private:
    std::shared_ptr<KindTally> tally_ = std::make_shared<KindTally>();
};

}  // namespace raystep::grade
