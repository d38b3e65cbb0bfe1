#include "app/report/audience.h"

namespace raystep::grade {

bool shown_to(const CheckResult& check, Audience audience) {
    return audience == Audience::instructor || check.visibility == Visibility::visible;
}

GradeReport seen_by(const GradeReport& report, Audience audience) {
    GradeReport seen = report;
    seen.checks.clear();
    for (const CheckResult& check : report.checks) {
        if (shown_to(check, audience)) seen.checks.push_back(check);
    }
    if (seen.checks.size() < report.checks.size()) {
        seen.times.checks = 0.0;
        for (const CheckResult& check : seen.checks)
            seen.times.checks += check.seconds;
        seen.times.reports = 0.0;
    }
    return seen;
}

const std::string& reproduce_command(const Counterexample& example, Audience audience) {
    return audience == Audience::student ? example.student_reproduce : example.reproduce;
}

}  // namespace raystep::grade
