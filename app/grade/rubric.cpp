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

CheckResult scored_check(std::string id, int stage, std::string kind, std::string name,
                         const RubricEntry& entry, Outcome measured, double fraction,
                         bool scorable) {
    CheckResult result;
    result.id = std::move(id);
    result.stage = stage;
    result.kind = std::move(kind);
    result.name = std::move(name);
    result.max_score = entry.points;
    result.visibility = entry.visibility;
    scorable =
        scorable && measured != Outcome::did_not_compile && measured != Outcome::not_implemented;
    result.score = scorable ? entry.score(fraction) : 0.0;
    // Passed means full points, in every report: the rubric may give full points short of every
    // case (a lecture method loses a few slivers by design), and Gradescope shows a test's status
    // in colour, so a check at its maximum must not read "failed", nor one short of it "passed"
    // (a speed check's partial points). A stub, a check that did not compile or could not measure
    // anything keeps its own outcome: it earned nothing. A check worth no points (reported only)
    // keeps what it measured.
    result.outcome = measured;
    if (scorable && entry.points > 0.0) {
        if (result.score >= entry.points) {
            result.outcome = Outcome::passed;
        } else if (measured == Outcome::passed) {
            result.outcome = Outcome::failed;
        }
    }
    return result;
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
