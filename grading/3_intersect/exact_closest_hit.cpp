#include <variant>

#include "grading/3_intersect/exact_hits.h"
#include "grading/3_intersect/exact_intersection.h"

namespace raystep {

namespace exact {

double rounded(const HitTime& time) {
    if (!time.is_root) return rounded(time.rational);
    return nearest_double_of_root(as_mpq(CGAL::exact(time.a)), as_mpq(CGAL::exact(time.b)),
                                  as_mpq(CGAL::exact(time.c)), as_mpq(CGAL::exact(time.disc)),
                                  time.smaller);
}

int compare(const HitTime& t1, const HitTime& t2) {
    if (!t1.is_root && !t2.is_root)
        return static_cast<int>(CGAL::compare(t1.rational, t2.rational));

    // A root involves a square root: evaluate both far beyond double precision instead.
    constexpr mpfr_prec_t kPrecision = 4096;
    mpfr_t v1, v2;
    mpfr_init2(v1, kPrecision);
    mpfr_init2(v2, kPrecision);
    const auto evaluate = [](mpfr_ptr out, const HitTime& t) {
        if (!t.is_root) {
            mpfr_set_q(out, as_mpq(CGAL::exact(t.rational)), MPFR_RNDN);
        } else if (CGAL::is_zero(t.disc) && CGAL::is_zero(t.b)) {
            mpfr_set_zero(out, 1);  // the double root -b / a with b = 0
        } else {
            evaluate_root(out, as_mpq(CGAL::exact(t.a)), as_mpq(CGAL::exact(t.b)),
                          as_mpq(CGAL::exact(t.c)), as_mpq(CGAL::exact(t.disc)), t.smaller);
        }
    };
    evaluate(v1, t1);
    evaluate(v2, t2);
    // Apart by more than the evaluations' error (8 roundings at 4096 bits): decided.
    mpfr_t difference, scale;
    mpfr_init2(difference, kPrecision);
    mpfr_init2(scale, kPrecision);
    mpfr_sub(difference, v1, v2, MPFR_RNDN);
    mpfr_abs(scale, v1, MPFR_RNDN);
    mpfr_mul_2si(scale, scale, -4000, MPFR_RNDN);
    int result = 0;
    if (mpfr_cmpabs(difference, scale) > 0) result = mpfr_sgn(difference) > 0 ? 1 : -1;
    mpfr_clears(v1, v2, difference, scale, static_cast<mpfr_ptr>(nullptr));
    return result;
}

}  // namespace exact

Expectation expect_primitive(const Ray& ray, const CaseShape& shape) {
    if (const auto* sphere = std::get_if<Sphere>(&shape)) return expect_sphere(ray, *sphere);
    if (const auto* triangle = std::get_if<Triangle>(&shape))
        return expect_triangle(ray, *triangle);
    return expect_plane(ray, std::get<Plane>(shape));
}

int exact_closest_primitive(const Ray& ray, const std::vector<CaseShape>& shapes) {
    // closest_hit's order: spheres, then triangles, then planes, each in list order; a strict <
    // keeps the first of equal t's.
    int best = -1;
    std::optional<exact::HitTime> best_time;
    for (const std::size_t kind : {std::size_t{0}, std::size_t{1}, std::size_t{2}}) {
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            if (shapes[k].index() != kind) continue;
            std::optional<exact::HitTime> time;
            if (const auto* sphere = std::get_if<Sphere>(&shapes[k])) {
                time = exact::sphere_hit_time(ray, *sphere);
            } else if (const auto* triangle = std::get_if<Triangle>(&shapes[k])) {
                time = exact::triangle_hit_time(ray, *triangle);
            } else {
                time = exact::plane_hit_time(ray, std::get<Plane>(shapes[k]));
            }
            if (time && (!best_time || exact::compare(*time, *best_time) < 0)) {
                best = static_cast<int>(k);
                best_time = time;
            }
        }
    }
    return best;
}

}  // namespace raystep
