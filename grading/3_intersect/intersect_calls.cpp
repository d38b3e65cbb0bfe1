#include "grading/3_intersect/intersect_calls.h"

#include <algorithm>
#include <stdexcept>

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

std::vector<CaseAnswer> answer_stage3_cases(const Stage3CasesQuestion& question) {
    const Stage3Method method = method_named(question.method);
    std::vector<CaseAnswer> answers;
    for (const RayCase& ray_case : question.cases)
        answers.push_back(run_method(method, ray_case));
    return answers;
}

std::uint64_t run_triangle_workload(const TriangleWorkloadQuestion& question) {
    const Stage3Method method = method_named(question.method);
    if (method.kind != Stage3Method::Kind::triangle) {
        throw std::invalid_argument(method.name + " is not a triangle test");
    }
    const std::vector<Triangle>& triangles = question.primitives.triangles;
    if (question.rays.size() != triangles.size()) throw std::invalid_argument("a ray per triangle");
    std::uint64_t hits = 0;
    for (int pass = 0; pass < question.repeat; ++pass) {
        for (std::size_t k = 0; k < question.rays.size(); ++k)
            hits += method.triangle(question.rays[k], triangles[k]).has_value();
    }
    return hits;
}

}  // namespace raystep::probe
