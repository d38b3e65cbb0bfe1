#include "renderer/view.h"

#include <array>
#include <utility>

namespace raystep {

namespace {

constexpr std::array<std::pair<View, std::string_view>, 10> kViews = {{
    {View::rays, "rays"},
    {View::depth, "depth"},
    {View::normal, "normal"},
    {View::barycentric, "barycentric"},
    {View::cost, "cost"},
    {View::uv, "uv"},
    {View::tangent, "tangent"},
    {View::shaded, "shaded"},
    {View::full, "full"},
    {View::indirect, "indirect"},
}};

}  // namespace

std::string_view view_name(View view) {
    for (const auto& [v, name] : kViews) {
        if (v == view) return name;
    }
    return "unknown";
}

std::optional<View> parse_view(std::string_view name) {
    for (const auto& [v, view_text] : kViews) {
        if (view_text == name) return v;
    }
    return std::nullopt;
}

std::vector<std::string> view_names() {
    std::vector<std::string> names;
    for (const auto& entry : kViews)
        names.emplace_back(entry.second);
    return names;
}

bool averages_samples(View view) {
    return view == View::shaded || view == View::full || view == View::indirect;
}

}  // namespace raystep
