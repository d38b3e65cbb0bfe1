#pragma once

#include <memory>
#include <string>
#include <vector>

#include "grader/grade/check_definition.h"

namespace raystep::grade {

/// The score of a check of one sentence of a contract that several functions must keep (stage 3's
/// "t_max is in the range", asked of every intersection test): the share of the functions that
/// keep it on every case they were asked, not the share of cases. A sentence broken in one
/// function is broken, however few of the check's cases that function has.
class FunctionShare {
  public:
    /// The case, its judge now also marking `function` as breaking the sentence when the answer is
    /// not right: a wrong answer, a stub's, none at all.
    ProbeCase counted(ProbeCase probe_case, const std::string& function);

    /// Makes the measure's fraction the share of the functions asked (those with a case judged)
    /// that answered every case right, and names the others in its summary. A measure that asked
    /// nothing, or that did not compile, is left as it is.
    void score(CheckMeasure& measure) const;

  private:
    struct Tally {
        std::vector<std::string> asked;   ///< in the order first judged
        std::vector<std::string> broken;  ///< the same order
    };
    std::shared_ptr<Tally> tally_ = std::make_shared<Tally>();
};

}  // namespace raystep::grade
