#include "app/report/grade_report.h"

#include <tuple>

#include <stdexcept>

namespace raystep::grade {

std::string outcome_name(Outcome outcome) {
    switch (outcome) {
        case Outcome::passed:
            return "passed";
        case Outcome::failed:
            return "failed";
        case Outcome::crashed:
            return "crashed";
        case Outcome::timed_out:
            return "timed out";
        case Outcome::not_implemented:
            return "not implemented";
        case Outcome::did_not_compile:
            return "did not compile";
    }
    // Reached only by a value cast from outside the enum.
    throw std::invalid_argument("outcome_name: not an Outcome: " +
                                std::to_string(static_cast<int>(outcome)));
}

std::string visibility_name(Visibility visibility) {
    switch (visibility) {
        case Visibility::visible:
            return "visible";
        case Visibility::hidden:
            return "hidden";
        case Visibility::after_due_date:
            return "after_due_date";
        case Visibility::after_published:
            return "after_published";
    }
    // Reached only by a value cast from outside the enum.
    throw std::invalid_argument("visibility_name: not a Visibility: " +
                                std::to_string(static_cast<int>(visibility)));
}

double GradeReport::score() const {
    double total = 0.0;
    for (const CheckResult& check : checks)
        total += check.score;
    return total;
}

double GradeReport::max_score() const {
    double total = 0.0;
    for (const CheckResult& check : checks)
        total += check.max_score;
    return total;
}

std::vector<std::pair<double, double>> GradeReport::stage_scores() const {
    std::vector<std::pair<double, double>> scores(kLastStage + 1, {0.0, 0.0});
    for (const CheckResult& check : checks) {
        // A stage out of range is the grader's bug: say which check has it rather than drop
        // its points from every total.
        if (check.stage < 0 || check.stage > kLastStage) {
            throw std::invalid_argument("check " + check.id + " has stage " +
                                        std::to_string(check.stage) + "; stages are 0 to " +
                                        std::to_string(kLastStage));
        }
        scores[static_cast<std::size_t>(check.stage)].first += check.score;
        scores[static_cast<std::size_t>(check.stage)].second += check.max_score;
    }
    return scores;
}

std::vector<StageTally> GradeReport::stage_tallies() const {
    const std::vector<std::pair<double, double>> scores = stage_scores();
    std::vector<StageTally> tallies;
    for (const int stage : kStageReportOrder) {
        StageTally tally;
        tally.stage = stage;
        std::tie(tally.score, tally.max_score) = scores[static_cast<std::size_t>(stage)];
        for (const CheckResult& check : checks) {
            if (check.stage != stage) continue;
            ++tally.checks;
            if (check.outcome == Outcome::passed) ++tally.passed;
        }
        if (tally.checks > 0) tallies.push_back(tally);
    }
    return tallies;
}

}  // namespace raystep::grade
