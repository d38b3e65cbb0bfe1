#include "grading/8_sampling/sampling_judges.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"
#include "app/protocol/json_codec.h"

namespace raystep::grade {

namespace {

using probe::Json;

std::vector<Vec2> points_from(const Json& j) {
    return probe::JsonCodec<std::vector<Vec2>>::read(j);
}

// Row by row, then along the row: the order the two lists are compared in.
bool before(const Vec2& p, const Vec2& q) {
    return p.y < q.y || (p.y == q.y && p.x < q.x);
}

const JudgeRegistry::Registration point_set_registration{
    {"point_set", [](const Json& p) -> Judge {
         std::vector<Vec2> expected = points_from(p.at("expected"));
         std::sort(expected.begin(), expected.end(), before);
         const double tolerance = probe::number_from(p.at("tolerance"));
         return [=](const ProbeAnswer& answer) {
             const std::string want = std::to_string(expected.size()) +
                                      " points in any order, within " + full_text(tolerance);
             if (answer.kind != ProbeAnswer::Kind::result) return verdict_wrong(want, "");
             std::vector<Vec2> got = points_from(answer.value);
             if (got.size() != expected.size()) {
                 return verdict_wrong(want, std::to_string(got.size()) + " points");
             }
             // Sorted both, then point by point: the points lie 1/n apart, far beyond the
             // tolerance, so rounding never swaps two of them. Written so that a NaN fails.
             std::sort(got.begin(), got.end(), before);
             for (std::size_t k = 0; k < got.size(); ++k) {
                 if (!(std::abs(got[k].x - expected[k].x) <= tolerance &&
                       std::abs(got[k].y - expected[k].y) <= tolerance)) {
                     return verdict_wrong(full_text(expected[k]), full_text(got[k]));
                 }
             }
             return verdict_right();
         };
     }}};

const JudgeRegistry::Registration sample_points_registration{
    {"sample_points", [](const Json& p) -> Judge {
         const int count = p.at("count").get<int>();
         return [=](const ProbeAnswer& answer) {
             const std::string want = std::to_string(count) + " points in [0, 1)^2";
             if (answer.kind != ProbeAnswer::Kind::result) return verdict_wrong(want, "");
             for (const std::vector<Vec2>& got :
                  probe::JsonCodec<std::vector<std::vector<Vec2>>>::read(answer.value)) {
                 if (got.size() != static_cast<std::size_t>(count)) {
                     return verdict_wrong(want, std::to_string(got.size()) + " points");
                 }
                 for (const Vec2& q : got) {
                     if (!(q.x >= 0 && q.x < 1 && q.y >= 0 && q.y < 1)) {
                         return verdict_wrong(want, full_text(q));
                     }
                 }
             }
             return verdict_right();
         };
     }}};

}  // namespace

Json point_set_judge(const std::vector<Vec2>& expected, double tolerance) {
    return {{"judge", "point_set"},
            {"expected", probe::JsonCodec<std::vector<Vec2>>::write(expected)},
            {"tolerance", probe::number(tolerance)}};
}

Json sample_points_judge(int count) {
    return {{"judge", "sample_points"}, {"count", count}};
}

}  // namespace raystep::grade
