// Counting the primitive tests a submission's stage-4 structure makes. The probe of stage 4 takes
// stage 3 from the reference, so every primitive test the structure makes is a call into one of
// stage 3's public functions: the probe is linked with `-Wl,--wrap=SYMBOL` for each of them
// (grader/CMakeLists.txt, stage3_counted_symbols), which sends the submission's calls to the
// counting functions below and theirs on to the real ones (`__real_SYMBOL`). The count is the
// grader's, not the structure's own TraversalStats, which a submission could report as it likes.
//
// What it cannot see: a submission that writes its own primitive tests into its stage-4 files, or
// names the `__real_` symbols itself. Its tests must then give exactly the reference's t on every
// ray of the structure checks, and the timed speed check still sees the work they do.

#include "grader/probe/stage3_test_count.h"

#include <optional>

#include "stages/3_intersect/intersect.h"

namespace raystep::probe {

namespace {

thread_local std::uint64_t tests_counted = 0;
// Above 0 while a counted call runs: stage 3's own calls inside it (closest_hit testing each
// primitive, a triangle test handing over to another) are part of the test already counted.
thread_local int depth = 0;

// Counts `tests` for a call from outside stage 3 and runs `call` one level deeper.
template <class Call>
auto counted(std::uint64_t tests, Call call) {
    if (depth == 0) tests_counted += tests;
    ++depth;
    struct Leave {
        ~Leave() { --depth; }
    } leave;
    return call();
}

}  // namespace

std::uint64_t stage3_tests_counted() {
    return tests_counted;
}

}  // namespace raystep::probe

// The real functions and their counting stand-ins, named as the linker's --wrap option names
// them. The mangled names are those of the declarations in stages/3_intersect/intersect.h. A
// macro, since an asm label names one declaration: no template can stand for the six.
#define RAYSTEP_COUNTED_TEST(MANGLED, NAME, Shape)                                         \
    std::optional<raystep::Hit> real_##NAME(const raystep::Ray&,                           \
                                            const raystep::Shape&) asm("__real_" MANGLED); \
    std::optional<raystep::Hit> counted_##NAME(                                            \
        const raystep::Ray& ray, const raystep::Shape& shape) asm("__wrap_" MANGLED);      \
    std::optional<raystep::Hit> counted_##NAME(const raystep::Ray& ray,                    \
                                               const raystep::Shape& shape) {              \
        return raystep::probe::counted(1, [&] { return real_##NAME(ray, shape); });        \
    }

RAYSTEP_COUNTED_TEST("_ZN7raystep15intersect_planeERKNS_3RayERKNS_5PlaneE", intersect_plane, Plane)
RAYSTEP_COUNTED_TEST("_ZN7raystep16intersect_sphereERKNS_3RayERKNS_6SphereE", intersect_sphere,
                     Sphere)
RAYSTEP_COUNTED_TEST("_ZN7raystep18intersect_triangleERKNS_3RayERKNS_8TriangleE",
                     intersect_triangle, Triangle)
RAYSTEP_COUNTED_TEST("_ZN7raystep25intersect_triangle_cramerERKNS_3RayERKNS_8TriangleE",
                     intersect_triangle_cramer, Triangle)
RAYSTEP_COUNTED_TEST("_ZN7raystep29intersect_triangle_halfspacesERKNS_3RayERKNS_8TriangleE",
                     intersect_triangle_halfspaces, Triangle)
RAYSTEP_COUNTED_TEST("_ZN7raystep29intersect_triangle_projectionERKNS_3RayERKNS_8TriangleE",
                     intersect_triangle_projection, Triangle)

std::optional<raystep::PrimitiveHit>
real_closest_hit(const raystep::Ray&, const raystep::PrimitiveList&) asm(
    "__real__ZN7raystep11closest_hitERKNS_3RayERKNS_13PrimitiveListE");
std::optional<raystep::PrimitiveHit>
counted_closest_hit(const raystep::Ray& ray, const raystep::PrimitiveList& list) asm(
    "__wrap__ZN7raystep11closest_hitERKNS_3RayERKNS_13PrimitiveListE");
std::optional<raystep::PrimitiveHit> counted_closest_hit(const raystep::Ray& ray,
                                                         const raystep::PrimitiveList& list) {
    const std::uint64_t tests = list.spheres.size() + list.triangles.size() + list.planes.size();
    return raystep::probe::counted(tests, [&] { return real_closest_hit(ray, list); });
}
