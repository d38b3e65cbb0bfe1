#include "grading/10_path_tracing/path_tracing_judges.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"
#include "grading/10_path_tracing/path_tracing_json.h"

namespace raystep::grade {

namespace {

using probe::Json;
using Kind = ProbeAnswer::Kind;

std::string frame_text(const Frame& f) {
    return "u " + full_text(f.u) + " v " + full_text(f.v) + " w " + full_text(f.w);
}

const JudgeRegistry::Registration frame_around_registration{
    {"frame_around", [](const Json& p) -> Judge {
         const Vec3 normal = probe::vec3_from(p.at("normal"));
         const double tolerance = probe::number_from(p.at("tolerance"));
         const std::string want = "an orthonormal frame with w " + full_text(normal) + " (within " +
                                  full_text(tolerance) + ")";
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(want, "");
             const Frame f = probe::JsonCodec<Frame>::read(answer.value);
             const bool right = near_double(f.w, normal, tolerance) &&
                                near_double(glm::dot(f.u, f.u), 1.0, tolerance) &&
                                near_double(glm::dot(f.v, f.v), 1.0, tolerance) &&
                                near_double(glm::dot(f.u, f.v), 0.0, tolerance) &&
                                near_double(glm::dot(f.u, f.w), 0.0, tolerance) &&
                                near_double(glm::dot(f.v, f.w), 0.0, tolerance);
             return right ? verdict_right() : verdict_wrong(want, frame_text(f));
         };
     }}};

const JudgeRegistry::Registration roulette_registration{
    {"roulette", [](const Json& p) -> Judge {
         const std::optional<Color> expected =
             probe::JsonCodec<std::optional<Color>>::read(p.at("expected"));
         const double tolerance = probe::number_from(p.at("tolerance"));
         const std::string want =
             expected ? full_text(*expected) + " (within " + full_text(tolerance) + ")"
                      : std::string("nullopt: the path stops");
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(want, "");
             const auto got = probe::JsonCodec<std::optional<Color>>::read(answer.value);
             if (!got) return expected ? verdict_wrong(want, "nullopt") : verdict_right();
             if (expected && near_double(*got, *expected, tolerance)) return verdict_right();
             return verdict_wrong(want, full_text(*got));
         };
     }}};

std::string sample_text(const LightDirectionSample& s) {
    return "direction " + full_text(s.direction) + ", distance " + full_text(s.distance) +
           ", pdf " + full_text(s.pdf) + ", radiance " + full_text(s.radiance);
}

const JudgeRegistry::Registration light_direction_sample_registration{
    {"light_direction_sample", [](const Json& p) -> Judge {
         const auto expected = probe::JsonCodec<LightDirectionSample>::read(p.at("expected"));
         const double direction_tolerance = probe::number_from(p.at("direction_tolerance"));
         const double relative = probe::number_from(p.at("relative"));
         const std::string want = sample_text(expected) + " (within " + full_text(relative) +
                                  " relative, the direction " + full_text(direction_tolerance) +
                                  ")";
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(want, "");
             const auto got = probe::JsonCodec<LightDirectionSample>::read(answer.value);
             const auto within = [&](double g, double e) {
                 return near_double(g, e, std::max(relative * std::abs(e), 1e-300));
             };
             const double brightest =
                 std::max({std::abs(expected.radiance.x), std::abs(expected.radiance.y),
                           std::abs(expected.radiance.z)});
             bool right = within(got.pdf, expected.pdf) &&
                          near_double(got.radiance, expected.radiance, relative * brightest);
             if (expected.pdf > 0) {
                 right = right &&
                         near_double(got.direction, expected.direction, direction_tolerance) &&
                         within(got.distance, expected.distance);
             }
             return right ? verdict_right() : verdict_wrong(want, sample_text(got));
         };
     }}};

}  // namespace

Json frame_around_judge(const Vec3& normal, double tolerance) {
    return {{"judge", "frame_around"},
            {"normal", probe::vec3(normal)},
            {"tolerance", probe::number(tolerance)}};
}

Json roulette_judge(const std::optional<Color>& expected, double tolerance) {
    return {{"judge", "roulette"},
            {"expected", probe::JsonCodec<std::optional<Color>>::write(expected)},
            {"tolerance", probe::number(tolerance)}};
}

Json light_direction_sample_judge(const LightDirectionSample& expected, double direction_tolerance,
                                  double relative) {
    return {{"judge", "light_direction_sample"},
            {"expected", probe::JsonCodec<LightDirectionSample>::write(expected)},
            {"direction_tolerance", probe::number(direction_tolerance)},
            {"relative", probe::number(relative)}};
}

}  // namespace raystep::grade
