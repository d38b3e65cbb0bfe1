#include "app/grade/render_judge.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "app/compare/render_rule.h"
#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"
#include "app/protocol/image_json.h"

namespace raystep::grade {

namespace {

using probe::Json;

const JudgeRegistry::Registration render_registration{
    {"render", [](const Json& p) -> Judge {
         const Image reference =
             probe::image_from(p.at("reference"), std::numeric_limits<std::size_t>::max());
         const std::string scene = p.at("scene").get<std::string>();
         const std::optional<View> view = parse_view(p.at("view").get<std::string>());
         if (!view) throw std::invalid_argument("no view " + p.at("view").dump());
         const int scene_width = p.at("scene_width").get<int>();
         const int scene_height = p.at("scene_height").get<int>();
         return [=](const ProbeAnswer& answer) {
             Verdict verdict;
             if (answer.kind != ProbeAnswer::Kind::result) {
                 verdict.expected = "an image";
                 return verdict;
             }
             const Image student = probe::image_from(
                 answer.value, static_cast<std::size_t>(reference.width()) * reference.height());
             const RenderVerdict rule = judge_render(reference, student);
             verdict.passed = rule.passed;
             verdict.fraction = 1.0 - rule.share_over;
             verdict.summary = render_summary(rule);
             if (rule.passed) return verdict;
             if (!rule.diff.same_size) {
                 verdict.expected = std::to_string(reference.width()) + " x " +
                                    std::to_string(reference.height()) + " pixels";
                 verdict.got = std::to_string(student.width()) + " x " +
                               std::to_string(student.height()) + " pixels";
                 return verdict;
             }
             const RenderPlace place = worst_render_place(scene, *view, scene_width, scene_height,
                                                          reference, student, kStudentBuildRaystep);
             verdict.expected = place.expected;
             verdict.got = place.got;
             verdict.place = place.input;
             verdict.place_reproduce = place.trace;
             return verdict;
         };
     }}};

}  // namespace

RenderPlace worst_render_place(const std::string& scene, View view, int scene_width,
                               int scene_height, const Image& reference, const Image& student,
                               const std::string& program) {
    int worst_i = 0;
    int worst_j = 0;
    double worst = 0.0;
    for (int j = 0; j < reference.height(); ++j) {
        for (int i = 0; i < reference.width(); ++i) {
            const Color d = glm::abs(reference.at(i, j) - student.at(i, j));
            const double largest =
                std::isnan(d.r + d.g + d.b) ? HUGE_VAL : std::max({d.r, d.g, d.b});
            if (largest > worst) {
                worst = largest;
                worst_i = i;
                worst_j = j;
            }
        }
    }
    // The same place at the scene's own size, where `raystep trace` looks.
    const int x = std::min(scene_width - 1,
                           static_cast<int>((worst_i + 0.5) * scene_width / reference.width()));
    const int y = std::min(scene_height - 1,
                           static_cast<int>((worst_j + 0.5) * scene_height / reference.height()));
    const std::string view_text(view_name(view));
    return {scene + ", " + view_text + " view, pixel (" + std::to_string(worst_i) + ", " +
                std::to_string(worst_j) + ") of the " + std::to_string(reference.width()) + " x " +
                std::to_string(reference.height()) + " render, pixel (" + std::to_string(x) + ", " +
                std::to_string(y) + ") at the scene's " + std::to_string(scene_width) + " x " +
                std::to_string(scene_height),
            full_text(reference.at(worst_i, worst_j)), full_text(student.at(worst_i, worst_j)),
            program + " trace scenes/" + scene + " " + std::to_string(x) + " " + std::to_string(y) +
                " --view " + view_text};
}

Json render_judge(const Image& reference, const std::string& scene, View view, int scene_width,
                  int scene_height) {
    return {{"judge", "render"},
            {"reference", probe::image(reference)},
            {"scene", scene},
            {"view", std::string(view_name(view))},
            {"scene_width", scene_width},
            {"scene_height", scene_height}};
}

}  // namespace raystep::grade
