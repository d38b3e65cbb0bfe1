#include "grader/grade/checks/data_judged.h"

#include "app/grade/data_judge.h"
#include "grader/grade/checks/stage_checks.h"

namespace raystep::grade {

ProbeCase data_judged_case(const PublicCase& c) {
    const Judge judge = build_judge(c.judge);
    return {c.input, c.query,
            [judge](const ProbeAnswer& answer) {
                const Verdict verdict = judge(answer);
                return Judgement{verdict.passed, verdict.expected, verdict.got,
                                 verdict.not_implemented};
            },
            c.reproduce};
}

std::vector<ProbeCase> data_judged_cases(const std::vector<PublicCase>& cases) {
    std::vector<ProbeCase> judged;
    judged.reserve(cases.size());
    for (const PublicCase& c : cases)
        judged.push_back(data_judged_case(c));
    return judged;
}

PublicCheck sample_check(int stage, std::string name, std::vector<PublicCase> cases) {
    return {"stage" + std::to_string(stage) + ".sample", stage, kSampleKind,
            std::move(name) + " (a sample)", std::move(cases)};
}

std::vector<PublicCheck> public_checks(const std::filesystem::path& source) {
    std::vector<PublicCheck> checks = {
        stage1_public_check(), stage1_sample_check(),      stage2_public_check(),
        stage2_sample_check(), stage4_slab_public_check(), stage4_grid_resolution_public_check(),
        stage4_sample_check(), stage5_public_check(),      stage5_sample_check(),
        stage6_public_check(), stage6_sample_check(),      stage7_public_check(),
        stage7_sample_check(), stage8_public_check(),      stage8_sample_check(),
    };
    checks.push_back(stage9_public_check());
    checks.push_back(stage9_sample_check());
    checks.push_back(stage10_public_check());
    checks.push_back(stage10_sample_check());
    checks.push_back(stage11_public_check());
    checks.push_back(stage11_sample_check());
    for (PublicCheck& check : render_public_checks(source))
        checks.push_back(std::move(check));
    return checks;
}

}  // namespace raystep::grade
