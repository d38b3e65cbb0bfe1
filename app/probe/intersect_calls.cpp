// Stage 3 calls: one stage-3 function over a list of ray cases (questions only: the probe never
// sees the oracle's expectations), answered as app/check answers them for `raystep check`; and
// a triangle test's workload, timed by the grader from outside, as the stage-4 workloads are.

#include <algorithm>
#include <stdexcept>

#include "app/check/stage3_methods.h"
#include "app/probe/call_table.h"

namespace raystep::probe {

namespace {

Stage3Method method_named(const std::string& name) {
    const std::vector<Stage3Method> methods = stage3_methods();
    const auto method = std::find_if(methods.begin(), methods.end(),
                                     [&](const Stage3Method& m) { return m.name == name; });
    if (method == methods.end()) throw std::invalid_argument("no stage-3 method " + name);
    return *method;
}

}  // namespace

void add_intersect_calls(CallTable& table) {
    table["stage3_cases"] = [](const Json& a) {
        const Stage3Method method = method_named(a.at("method").get<std::string>());
        Json answers = Json::array();
        for (const Json& question : a.at("cases")) {
            answers.push_back(case_answer(run_method(method, case_question_from(question))));
        }
        return answers;
    };
    // rays[k] against triangles[k], every pair `repeat` times; the hits counted, so that no call
    // can be optimized away, are the answer.
    table["triangle_workload"] = [](const Json& a) {
        const Stage3Method method = method_named(a.at("method").get<std::string>());
        if (method.kind != Stage3Method::Kind::triangle) {
            throw std::invalid_argument(method.name + " is not a triangle test");
        }
        const std::vector<Ray> rays = rays_from(a.at("rays"));
        const std::vector<Triangle> triangles = primitive_list_from(a.at("primitives")).triangles;
        if (rays.size() != triangles.size()) throw std::invalid_argument("a ray per triangle");
        const int repeat = a.at("repeat").get<int>();
        std::size_t hits = 0;
        for (int pass = 0; pass < repeat; ++pass) {
            for (std::size_t k = 0; k < rays.size(); ++k) {
                hits += method.triangle(rays[k], triangles[k]).has_value();
            }
        }
        return Json(hits);
    };
}

}  // namespace raystep::probe
