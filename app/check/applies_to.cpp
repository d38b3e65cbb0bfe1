// applies_to is declared with the methods (stage3_methods.h) but defined here, in raystep_protocol:
// scoring needs it, and the library that scores must not link any stage's code.

#include <variant>

#include "app/check/stage3_methods.h"

namespace raystep {

bool applies_to(const Stage3Method& method, const CaseShape& shape) {
    switch (method.kind) {
        case Stage3Method::Kind::sphere:
            return std::holds_alternative<Sphere>(shape);
        case Stage3Method::Kind::triangle:
            return std::holds_alternative<Triangle>(shape);
        case Stage3Method::Kind::plane:
            return std::holds_alternative<Plane>(shape);
        case Stage3Method::Kind::closest:
            return true;
    }
    return false;
}

}  // namespace raystep
