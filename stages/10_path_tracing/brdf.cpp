// Stage 10: the CSE168 course's Phong and GGX BRDFs. Handout: docs/stage10.md.

#include "base/errors/not_implemented.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

Color evaluate_brdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_light,
                    const Vec3& to_eye) {
    // 0 unless n . wi > 0 and n . wo > 0. Then Kd / pi plus
    //   phong: Ks (s + 2) / (2 pi) (r . wi)^s where r . wi > 0, r = reflect(-wo, n);
    //   ggx:   F G D / (4 (n . wi)(n . wo)), h = normalize(wi + wo).
    RAYSTEP_TODO(10, "evaluate_brdf", "The BRDF");
}

}  // namespace raystep
