// The order a grade starts its checks in (check_start_order): a check that shares another's
// measurement waits for it, so it starts once every other check has, and no worker sits idle
// while the measurement it waits for is made.

#include <map>
#include <string>
#include <vector>

#include "base/testing/catch.h"
#include "grader/grade/check_definition.h"

using namespace raystep::grade;

namespace {

CheckDefinition check(const std::string& id, const std::string& kind,
                      const std::string& measured_by = "") {
    CheckDefinition made{id, 4, kind, "a check", {}};
    made.measured_by = measured_by;
    return made;
}

}  // namespace

TEST_CASE("checks measured by another start after every other check, speed checks not at all",
          "[grader]") {
    const std::vector<CheckDefinition> checks = {
        check("a", "oracle"), check("b", "oracle", "a"), check("c", "oracle"),
        check("d", "speed"),  check("e", "oracle", "c"), check("f", "render"),
    };
    CHECK(check_start_order(checks) == std::vector<std::size_t>{0, 2, 5, 1, 4});
}

TEST_CASE("every check measured by another names a check of its stage that measures for itself",
          "[grader]") {
    const std::vector<CheckDefinition> checks = all_checks();
    std::map<std::string, const CheckDefinition*> by_id;
    for (const CheckDefinition& check : checks)
        by_id[check.id] = &check;
    int sharing = 0;
    for (const CheckDefinition& check : checks) {
        if (check.measured_by.empty()) continue;
        ++sharing;
        INFO(check.id << " is measured by " << check.measured_by);
        REQUIRE(by_id.count(check.measured_by) == 1);
        CHECK(by_id[check.measured_by]->stage == check.stage);
        CHECK(by_id[check.measured_by]->measured_by.empty());
    }
    // Stage 4: the median BVH and occluded share the SAH BVH's walk, the grid's occluded the
    // grid's.
    CHECK(sharing == 3);
}
