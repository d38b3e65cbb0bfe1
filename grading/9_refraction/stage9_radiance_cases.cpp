#include "grading/9_refraction/stage9_radiance_cases.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include <glm/geometric.hpp>

#include "grader/grade/checks/case_text.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grading/9_refraction/refraction_calls.h"
#include "grading/9_refraction/refraction_judges.h"
#include "grading/9_refraction/refraction_oracle.h"

namespace raystep::grade {

namespace {

using probe::Json;

const double kInf = std::numeric_limits<double>::infinity();

const Medium kGlass{1, 1.5};
const Medium kWater{2, 1.33};
const Medium kDiamond{3, 2.4};

// --- How a case is written

std::string media_text(const MediumStack& stack) {
    std::string text;
    for (const Medium& m : stack)
        text +=
            (text.empty() ? "" : ", ") + std::to_string(m.solid) + " (" + full_text(m.index) + ")";
    return "[" + text + "]";
}

std::string cpp(const Medium& m) {
    return "Medium{" + std::to_string(m.solid) + ", " + grade::cpp(m.index) + "}";
}

std::string cpp(const MediumStack& stack) {
    std::string text;
    for (const Medium& m : stack)
        text += (text.empty() ? "" : ", ") + cpp(m);
    return "MediumStack{" + text + "}";
}

std::string cpp(const MediumHit& hit) {
    return "MediumHit{" + grade::cpp(hit.shaded) + ", " + grade::cpp(hit.transmission) + ", " +
           cpp(hit.solid) + ", " + (hit.entering ? "true" : "false") + "}";
}

std::string scene_text(const std::vector<KeyedHit>& scene) {
    std::string text;
    for (const KeyedHit& entry : scene) {
        const MediumHit& hit = entry.hit;
        text += (text.empty() ? "" : "; ") + std::string("for the ray ") + ray_text(entry.key) +
                ": hit at " + point_text(hit.shaded.point) + ", local " +
                full_text(hit.shaded.local) + ", Ks " + full_text(hit.shaded.reflectance) +
                ", Kt " + full_text(hit.transmission) + ", " +
                (hit.entering ? "entering " : "leaving ") + "solid " +
                std::to_string(hit.solid.solid) + " of index " + full_text(hit.solid.index);
    }
    return "[" + text + "]";
}

// The call in a student's test: shade answers each entry's hit for a ray that starts within 1 of
// its key's origin and runs within 0.01 of its direction, as the probe's does.
std::string radiance_code(const std::vector<KeyedHit>& scene, const Ray& eye, int bounces,
                          const MediumStack& inside, bool schlick, const RayOffset& offset) {
    std::string entries;
    for (const KeyedHit& entry : scene) {
        entries += (entries.empty() ? "" : ",\n    ") + std::string("{") + grade::cpp(entry.key) +
                   ", " + cpp(entry.hit) + "}";
    }
    return "const std::vector<std::pair<Ray, MediumHit>> scene = {\n    " + entries +
           "};\n"
           "std::vector<Ray> asked;  // every ray radiance_with_refraction asks shade about\n"
           "const MediumShadeFunction shade = [&](const Ray& ray) -> std::optional<MediumHit> {\n"
           "    asked.push_back(ray);\n"
           "    for (const auto& [key, hit] : scene) {\n"
           "        if (glm::length(ray.origin - key.origin) <= 1 &&\n"
           "            glm::length(ray.direction - key.direction) <= 0.01)\n"
           "            return hit;\n"
           "    }\n"
           "    return std::nullopt;\n"
           "};\n"
           "radiance_with_refraction(shade, " +
           grade::cpp(eye) + ", " + std::to_string(bounces) + ", " + cpp(inside) + ", " +
           (schlick ? "true" : "false") + ", " + grade::cpp(offset) + ")";
}

PublicCase radiance_case(const HitMaker& make, const Ray& eye, int bounces,
                         const MediumStack& inside, bool schlick, const RayOffset& offset) {
    const ExpectedRefractionRadiance e =
        expected_radiance_with_refraction(make, eye, bounces, inside, schlick, offset);
    return {"radiance_with_refraction(eye " + ray_text(eye) + ", bounces " +
                std::to_string(bounces) + ", inside " + media_text(inside) + ", " +
                (schlick ? "Schlick" : "exact Fresnel") + ", " + offset_text(offset) +
                ") over the scene " + scene_text(e.scene),
            probe::query(probe::radiance_with_refraction_call,
                         {e.scene, eye, bounces, inside, schlick, offset}),
            refraction_radiance_judge(double_double(e.colour), double_double(e.colour_tolerance),
                                      e.rays),
            radiance_code(e.scene, eye, bounces, inside, schlick, offset)};
}

// --- Hand-made scenes

// The hits of a hand-made scene in the order the oracle asks for them (depth first, the
// reflected ray before the refracted one); past the end, misses.
HitMaker listed(std::vector<std::optional<MediumHit>> hits) {
    auto next = std::make_shared<std::size_t>(0);
    return [hits = std::move(hits), next](const Ray&, const MediumStack&) {
        return *next < hits.size() ? hits[(*next)++] : std::nullopt;
    };
}

// The k-th hit of a hand-made scene sits 40 units along x past the (k-1)-th, so that no two
// hits' keys meet (refraction_calls.cpp).
SurfacePoint scene_point(int k, const Vec3& to_eye, const Vec3& normal) {
    const Vec3 n = glm::normalize(normal);
    return {{40.0 * (k + 1), 0, 0}, {0, 0, 0}, n, n, glm::normalize(to_eye)};
}

MediumHit surface(int k, const Vec3& to_eye, const Vec3& normal, const Color& local,
                  const Color& ks, const Color& kt, const Medium& solid, bool entering) {
    return {{scene_point(k, to_eye, normal), local, ks}, kt, solid, entering};
}

// A clear glass surface whose shading normal is bent from the geometric one.
MediumHit bent_glass(int k, const Vec3& to_eye, const Vec3& normal, const Vec3& shading_normal,
                     bool entering) {
    MediumHit hit = surface(k, to_eye, normal, Color(0.1), Color(0), Color(1), kGlass, entering);
    hit.shaded.point.shading_normal = glm::normalize(shading_normal);
    return hit;
}

// Clear glass seen head-on with V = N = unit_vector_squaring_above_one(), kept as they are:
// normalizing that vector again could round it to another.
MediumHit head_on_glass_above_one(int k, bool entering) {
    const Vec3 v = unit_vector_squaring_above_one();
    MediumHit hit = surface(k, v, v, Color(0.1), Color(0), Color(1), kGlass, entering);
    hit.shaded.point.normal = v;
    hit.shaded.point.shading_normal = v;
    hit.shaded.point.to_eye = v;
    return hit;
}

// An opaque, matte surface: it adds its local colour and sends nothing on.
MediumHit matte(int k, const Color& local) {
    return surface(k, {0, 1, 0}, {0, 1, 0}, local, Color(0), Color(0), kGlass, true);
}

const Ray kEye{{0, 0, 0}, {1, 0, 0}, 0.0, kInf};
const RayOffset kAlongRay{OffsetRule::along_ray, 1e-4};
const RayOffset kAlongNormal{OffsetRule::along_normal, 1e-4};
const RayOffset kErrorBound{OffsetRule::error_bound, 0.0};
const Color kRed{1, 0, 0};
const Color kGreen{0, 1, 0};
const Color kBlue{0, 0, 1};

// Glass seen head-on from air: 4% reflected, 96% refracted.
HitMaker head_on_glass(const Color& ks, const Color& kt) {
    return listed({surface(0, {0, 1, 0}, {0, 1, 0}, Color(0.1), ks, kt, kGlass, true),
                   matte(1, kRed), matte(2, kBlue)});
}

// Inside glass, 60 degrees from the normal: beyond the critical angle (41.8 degrees), so all of
// Kt goes into the reflected ray.
HitMaker glass_beyond_critical() {
    return listed({surface(0, {std::sqrt(3.0) / 2, 0.5, 0}, {0, 1, 0}, Color(0.1), Color(0),
                           Color(1), kGlass, false),
                   matte(1, kGreen)});
}

}  // namespace

std::vector<PublicCase> stage9_public_radiance_cases() {
    return {
        radiance_case(head_on_glass(Color(0), Color(1)), kEye, 1, {}, false, kAlongRay),
        radiance_case(glass_beyond_critical(), kEye, 1, {kGlass}, false, kAlongRay),
        // Into glass at 45 degrees, then into water inside the glass: the second surface bends
        // from 1.5 to 1.33, the indices the first crossing put the ray between.
        radiance_case(
            listed({surface(0, {1, 1, 0}, {0, 1, 0}, Color(0), Color(0), Color(0.9), kGlass, true),
                    std::nullopt,
                    surface(2, {-1, 2, 0}, {0, 1, 0}, Color(0), Color(0), Color(0.9), kWater, true),
                    std::nullopt, matte(4, Color(1))}),
            kEye, 3, {}, false, kAlongRay),
    };
}

std::vector<PublicCase> stage9_hidden_radiance_cases() {
    const HitMaker reflected_into_diamond =
        listed({surface(0, {1, 1, 0}, {0, 1, 0}, Color(0.1), Color(0.5), Color(0.5), kGlass, true),
                surface(1, {1, std::sqrt(3.0), 0}, {0, 1, 0}, Color(0), Color(0), Color(1),
                        kDiamond, true),
                matte(2, kRed), matte(3, kGreen), matte(4, kBlue)});
    return {
        // F once in each weight: Ks + Kt F reflected, Kt (1 - F) refracted, at 60 degrees.
        radiance_case(listed({surface(0, {std::sqrt(3.0), 1, 0}, {0, 1, 0}, Color(0.1), {0.2, 0, 0},
                                      {1, 0.5, 0.25}, kGlass, true),
                              matte(1, kRed), matte(2, kBlue)}),
                      kEye, 2, {}, false, kAlongNormal),
        radiance_case(head_on_glass({0, 0.3, 0}, {0.5, 1, 0}), kEye, 4, {}, true, kErrorBound),
        // Schlick leaving glass at 30 degrees: its cosine is the air side's, cos(48.6 degrees).
        radiance_case(listed({surface(0, {1, std::sqrt(3.0), 0}, {0, 1, 0}, Color(0.1), Color(0),
                                      Color(1), kGlass, false),
                              matte(1, kRed), matte(2, kBlue)}),
                      kEye, 1, {kGlass}, true, kAlongRay),
        radiance_case(glass_beyond_critical(), kEye, 3, {kGlass}, true, kAlongNormal),
        radiance_case(glass_beyond_critical(), kEye, 3, {kGlass}, false, kErrorBound),
        // The reflected ray stays in air: it meets the diamond coming from index 1, not 1.5.
        radiance_case(reflected_into_diamond, kEye, 3, {}, false, kAlongRay),
        radiance_case(reflected_into_diamond, kEye, 3, {}, true, kAlongNormal),
        // Overlapping solids: leaving the glass while in the water that was entered after it
        // leaves the ray in water, 1.33 on both sides, so it goes straight on; then out of the
        // water into air.
        radiance_case(
            listed(
                {surface(0, {1, 2, 0}, {0, 1, 0}, Color(0), Color(0.25), Color(1), kGlass, false),
                 matte(1, kRed),
                 surface(2, {1, 3, 0}, {0, 1, 0}, Color(0), Color(0.25), Color(1), kWater, false),
                 matte(3, kGreen), matte(4, kBlue)}),
            kEye, 3, {kGlass, kWater}, false, kAlongRay),
        // The same glass entered twice (a seam) and left once: still in glass, straight on;
        // then leaving it for good bends into air.
        radiance_case(
            listed(
                {surface(0, {1, 2, 0}, {0, 1, 0}, Color(0), Color(0.25), Color(1), kGlass, true),
                 matte(1, kRed),
                 surface(2, {1, 3, 0}, {0, 1, 0}, Color(0), Color(0.25), Color(1), kGlass, false),
                 matte(3, kGreen),
                 surface(4, {1, 4, 0}, {0, 1, 0}, Color(0), Color(0.25), Color(1), kGlass, false),
                 matte(5, kRed), matte(6, kBlue)}),
            kEye, 4, {kGlass}, false, kAlongNormal),
        // Leaving water the ray never entered changes nothing: from glass into glass.
        radiance_case(
            listed({surface(0, {1, 2, 0}, {0, 1, 0}, Color(0), Color(0.5), Color(1), kWater, false),
                    matte(1, kRed), matte(2, kBlue)}),
            kEye, 2, {kGlass}, false, kAlongRay),
        // Bounces cut: none left, or fewer than none.
        radiance_case(head_on_glass(Color(0.5), Color(1)), kEye, 0, {}, false, kAlongRay),
        radiance_case(head_on_glass(Color(0.5), Color(1)), kEye, -1, {}, false, kAlongRay),
        // Black weights trace nothing: an opaque black mirror; a mirror without glass.
        radiance_case(head_on_glass(Color(0), Color(0)), kEye, 3, {}, false, kAlongRay),
        radiance_case(head_on_glass({0, 0, 0.5}, Color(0)), kEye, 3, {}, false, kAlongRay),
        // Glass in one channel only: both weights are green, neither is black.
        radiance_case(head_on_glass(Color(0), kGreen), kEye, 3, {}, true, kAlongRay),
    };
}

std::vector<PublicCase> stage9_latest_entry_radiance_cases() {
    const MediumStack glass_water_glass{kGlass, kWater, kGlass};
    return {
        // Inside glass, water, glass, leaving the glass: the ray goes on in water, 1.5 to 1.33.
        radiance_case(
            listed({surface(0, {1, 2, 0}, {0, 1, 0}, Color(0), Color(0), Color(1), kGlass, false),
                    matte(1, kRed), matte(2, kBlue)}),
            kEye, 1, glass_water_glass, false, kAlongRay),
        // Then leaving the water too: from 1.33 back into the first glass's 1.5.
        radiance_case(
            listed({surface(0, {1, 2, 0}, {0, 1, 0}, Color(0), Color(0), Color(1), kGlass, false),
                    matte(1, kRed),
                    surface(2, {1, 3, 0}, {0, 1, 0}, Color(0), Color(0), Color(1), kWater, false),
                    matte(3, kGreen), matte(4, kBlue)}),
            kEye, 3, glass_water_glass, true, kAlongNormal),
    };
}

std::vector<PublicCase> stage9_shading_normal_radiance_cases() {
    const auto scene = [](const MediumHit& hit) {
        return listed({hit, matte(1, kRed), matte(2, kBlue)});
    };
    // cos(theta1) from the shading normal against the geometric one: 0.51 and 0.71 into glass
    // (F 0.085 and 0.050), 0.82 and 0.95 out of it (F 0.088 and 0.041); the reflected and the
    // refracted rays leave at least 0.29 off the geometric tangent plane, each on its own side.
    const MediumHit entering = bent_glass(0, {1, 1, 0}, {0, 1, 0}, {-0.25, 1, 0}, true);
    const MediumHit leaving = bent_glass(0, {1, 3, 0}, {0, 1, 0}, {-0.3, 1, 0}, false);
    const MediumHit entering_3d = bent_glass(0, {1, 2, 0.5}, {0, 1, 0}, {0.2, 1, -0.3}, true);
    const MediumHit leaving_3d = bent_glass(0, {-1, 3, 0.5}, {0, 1, 0}, {0.25, 1, 0.2}, false);
    return {
        radiance_case(scene(entering), kEye, 1, {}, false, kAlongNormal),
        radiance_case(scene(leaving), kEye, 1, {kGlass}, false, kErrorBound),
        radiance_case(scene(entering_3d), kEye, 1, {}, true, kAlongRay),
        radiance_case(scene(leaving_3d), kEye, 1, {kGlass}, true, kAlongNormal),
    };
}

std::vector<PublicCase> stage9_cosine_above_one_radiance_cases() {
    const auto scene = [](bool entering) {
        return listed({head_on_glass_above_one(0, entering), matte(1, kRed), matte(2, kBlue)});
    };
    return {
        radiance_case(scene(true), kEye, 1, {}, false, kAlongRay),
        radiance_case(scene(false), kEye, 1, {kGlass}, false, kAlongNormal),
        radiance_case(scene(true), kEye, 1, {}, true, kErrorBound),
        radiance_case(scene(false), kEye, 1, {kGlass}, true, kAlongRay),
    };
}

Vec3 unit_vector_squaring_above_one() {
    const double c = 0.5773502691896258;  // 1 / sqrt(3) rounded: its square rounds up
    return {c, c, c};
}

PublicCase stage9_random_radiance_case(PortableRandom& random, int k) {
    const Medium solids[] = {kGlass, kWater, kDiamond};
    int placed = 0;
    // A hit for each ray the oracle asks about: 40 units along x past the last one, seen along
    // the ray, its normal at least 0.2 from the tangent plane and, where light goes through,
    // sin^2(theta2) at least 0.01 from 1, so that no right answer sits on the critical angle and
    // the two rays leaving it are far apart in direction.
    const HitMaker make = [&](const Ray& key,
                              const MediumStack& inside) -> std::optional<MediumHit> {
        if (random.unit() < 0.15) return std::nullopt;
        ++placed;
        MediumHit hit;
        SurfacePoint& p = hit.shaded.point;
        p.position = Vec3(40.0 * placed, 0, 0) + random.unit_vector() * random.uniform(0, 5);
        const double size =
            std::max({std::abs(p.position.x), std::abs(p.position.y), std::abs(p.position.z)});
        const double error =
            random.unit() < 0.3 ? 0.0 : std::ldexp(size, -52) * random.decade(0, 2);
        p.error = {random.uniform(0, error), random.uniform(0, error), random.uniform(0, error)};
        p.to_eye = glm::normalize(-key.direction);
        hit.solid = solids[random.integer(0, 2)];
        hit.entering = random.unit() < 0.5;
        hit.transmission =
            random.unit() < 0.25
                ? Color(0)
                : Color(random.uniform(0.2, 1), random.uniform(0.2, 1), random.uniform(0.2, 1));
        hit.shaded.reflectance = random.unit() < 0.35 ? Color(0) : Color(random.uniform(0, 0.5));
        hit.shaded.local = {random.unit(), random.unit(), random.unit()};
        const MediumStack beyond = expected_after_crossing(inside, hit.solid, hit.entering);
        const double eta = expected_current_index(inside) / expected_current_index(beyond);
        for (;;) {
            p.normal = random.unit_vector();
            if (glm::dot(p.normal, p.to_eye) < 0) p.normal = -p.normal;
            const double cos1 = glm::dot(p.normal, p.to_eye);
            const double q = 1 - eta * eta * (1 - cos1 * cos1);
            if (cos1 >= 0.2 && std::abs(q) >= 0.01) break;
        }
        p.shading_normal = p.normal;
        // Where the two sides' indices are equal F is 0 up to rounding: a black mirror's
        // reflected ray would be traced or not by rounding alone.
        if (hit.shaded.reflectance == Color(0.0) && eta == 1.0) hit.shaded.reflectance = Color(0.1);
        return hit;
    };
    const MediumStack starts[] = {{}, {}, {kGlass}, {kGlass, kWater}};
    const MediumStack inside = starts[random.integer(0, 3)];
    const Ray eye{random.unit_vector() * 5.0, glm::normalize(random.unit_vector()), 0.0, kInf};
    const OffsetRule rules[] = {OffsetRule::along_ray, OffsetRule::along_normal,
                                OffsetRule::error_bound};
    const OffsetRule rule = rules[k % 3];
    const RayOffset offset{rule, rule == OffsetRule::error_bound ? 0.0 : random.decade(-6, -3)};
    const int bounces = static_cast<int>(random.integer(0, 5));
    return radiance_case(make, eye, bounces, inside, k % 2 == 1, offset);
}

}  // namespace raystep::grade
