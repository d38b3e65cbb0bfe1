#include "core/bench/pareto_registry.h"

namespace raystep {

namespace {

// A function-local static, so that a registration from another file's static object finds it
// built whatever order the linker put the files in.
ParetoStudy& registered() {
    static ParetoStudy study = nullptr;
    return study;
}

}  // namespace

void register_pareto_study(ParetoStudy study) {
    registered() = study;
}

ParetoStudy registered_pareto_study() {
    return registered();
}

ParetoStudyRegistration::ParetoStudyRegistration(ParetoStudy study) {
    register_pareto_study(study);
}

}  // namespace raystep
