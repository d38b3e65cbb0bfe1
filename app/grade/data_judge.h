#pragma once

#include <functional>
#include <optional>
#include <string>

#include "app/probe/probe_answer.h"
#include "base/program/static_registry.h"

namespace raystep::grade {

// A judge written as data: {"judge": NAME, ...parameters} in a public case file (public_case.h).
// The grader decides a public case's expectation when the release is written and judges its own
// run of that case with the same named judge, built from the same parameters, so that
// `raystep grade` in a release and the grade agree on every public case without the release
// holding the oracle that decided them.

/// What a judge makes of one answer: passed, or what was expected and what was got (empty when
/// the answer itself says it, an exception or a stub). `not_implemented` is a stub's message when
/// the stub's answer sat inside a result.
struct Verdict {
    bool passed = false;
    std::string expected;
    std::string got;
    std::string not_implemented;
    /// A judge that measures a share rather than right or wrong (a render's pixels that match
    /// the reference's): the share, which a check of that one case scores in place of its share
    /// of cases passed, and the line that says it. Unset for right-or-wrong judges.
    std::optional<double> fraction;
    std::string summary;
    /// Where the answer went wrong, when the judge can say it more precisely than the case's
    /// input (a render's worst pixel), and the student's command that shows that place. Empty
    /// otherwise.
    std::string place;
    std::string place_reproduce;
};

/// A right answer's verdict.
Verdict verdict_right();

/// A wrong answer's: what was expected, and what was got ("" where the answer itself says it).
Verdict verdict_wrong(std::string expected, std::string got);

using Judge = std::function<Verdict(const ProbeAnswer&)>;

/// A named judge and how it is built from its parameters (the judge's JSON object, "judge"
/// included). `build` throws std::invalid_argument, or nlohmann's json::exception, for a missing
/// or ill-typed parameter.
struct DataJudge {
    std::string name;
    std::function<Judge(const probe::Json& parameters)> build;
};

/// Every data judge, each registered by the file that defines it (app/grade/*_judges.cpp).
using JudgeRegistry = StaticRegistry<DataJudge>;

/// The judge `spec` names, built from its parameters. Throws std::invalid_argument naming an
/// unknown judge, or what `build` throws.
Judge build_judge(const probe::Json& spec);

}  // namespace raystep::grade
