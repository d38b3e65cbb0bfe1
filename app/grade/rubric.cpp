#include "app/grade/rubric.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace raystep::grade {

double RubricEntry::score(double fraction) const {
    if (!(fraction > zero_at)) return 0.0;
    if (fraction >= full_at) return points;
    return points * (fraction - zero_at) / (full_at - zero_at);
}

const RubricEntry& Rubric::entry(const std::string& id) const {
    const auto found = checks.find(id);
    if (found == checks.end()) throw std::out_of_range("the rubric has no entry for check " + id);
    return found->second;
}

namespace {

Visibility visibility_from(const std::string& name) {
    for (const Visibility v : {Visibility::visible, Visibility::hidden, Visibility::after_due_date,
                               Visibility::after_published}) {
        if (visibility_name(v) == name) return v;
    }
    throw std::invalid_argument("unknown visibility '" + name +
                                "' (visible, hidden, after_due_date, after_published)");
}

}  // namespace

Rubric load_rubric(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot be read");
    Rubric rubric;
    try {
        const nlohmann::json j = nlohmann::json::parse(in, nullptr, true, true);
        for (const auto& [id, e] : j.at("checks").items()) {
            RubricEntry entry;
            entry.points = e.at("points").get<double>();
            entry.full_at = e.value("full_at", 1.0);
            entry.zero_at = e.value("zero_at", 0.0);
            entry.visibility = visibility_from(e.value("visibility", "visible"));
            if (!(entry.points >= 0.0) || !(entry.zero_at < entry.full_at)) {
                throw std::invalid_argument(id + ": points must be >= 0 and zero_at below full_at");
            }
            rubric.checks[id] = entry;
        }
    } catch (const std::exception& error) {
        throw std::runtime_error(file.string() + ": " + error.what());
    }
    return rubric;
}

}  // namespace raystep::grade
