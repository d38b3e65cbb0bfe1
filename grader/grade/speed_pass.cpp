#include "grader/grade/speed_pass.h"

#include <algorithm>
#include <map>
#include <string>

#include "grader/grade/check_definition.h"

namespace raystep::grade {

namespace {

// Each check's place in all_checks(), where the grader's report lists it.
std::map<std::string, std::size_t> check_order() {
    std::map<std::string, std::size_t> order;
    const std::vector<CheckDefinition> checks = all_checks();
    for (std::size_t k = 0; k < checks.size(); ++k)
        order[checks[k].id] = k;
    return order;
}

}  // namespace

bool lacks_speed_checks(const GradeReport& report) {
    for (const CheckDefinition& check : all_checks()) {
        if (check.kind != "speed") continue;
        const bool present =
            std::any_of(report.checks.begin(), report.checks.end(),
                        [&](const CheckResult& result) { return result.id == check.id; });
        if (!present) return true;
    }
    return false;
}

GradeReport with_speed_checks(GradeReport first, const GradeReport& speed) {
    for (const CheckResult& result : speed.checks) {
        const auto same = [&](const CheckResult& c) { return c.id == result.id; };
        first.checks.erase(std::remove_if(first.checks.begin(), first.checks.end(), same),
                           first.checks.end());
        first.checks.push_back(result);
    }
    const std::map<std::string, std::size_t> order = check_order();
    const auto place = [&](const CheckResult& c) {
        const auto found = order.find(c.id);
        return found == order.end() ? order.size() : found->second;
    };
    std::stable_sort(
        first.checks.begin(), first.checks.end(),
        [&](const CheckResult& a, const CheckResult& b) { return place(a) < place(b); });
    first.times.intake += speed.times.intake;
    first.times.build += speed.times.build;
    first.times.checks += speed.times.checks;
    return first;
}

}  // namespace raystep::grade
