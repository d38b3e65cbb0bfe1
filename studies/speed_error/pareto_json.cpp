#include "studies/speed_error/pareto_json.h"

namespace raystep {

nlohmann::json pareto_family_json(const ParetoFamily& family) {
    nlohmann::json points = nlohmann::json::array();
    for (const ParetoPoint& p : family.points) {
        points.push_back(
            {{"label", p.label},
             {"precision", p.precision},
             {"function", p.function},
             {"cases", p.cases},
             {"false_hits", p.false_hits},
             {"false_misses", p.false_misses},
             {"wrong_share", p.wrong_share()},
             {"t_ulps",
              {{"median", p.t_ulps_median}, {"p99", p.t_ulps_p99}, {"max", p.t_ulps_max}}},
             {"mrays_per_second", p.mrays_per_second}});
    }
    return {{"name", family.name},
            {"description", family.description},
            {"cases", family.cases},
            {"points", points}};
}

nlohmann::json pareto_json(const std::string& machine, const std::string& date,
                           const std::vector<ParetoFamily>& families,
                           const std::vector<OffsetRuleResult>& offset_rules) {
    nlohmann::json json;
    json["study"] = "pareto";
    json["machine"] = machine;
    json["date"] = date;
    json["families"] = nlohmann::json::array();
    for (const ParetoFamily& family : families)
        json["families"].push_back(pareto_family_json(family));
    json["offset_rules"] = nlohmann::json::array();
    for (const OffsetRuleResult& r : offset_rules) {
        json["offset_rules"].push_back({{"scene", r.scene},
                                        {"rule", r.rule},
                                        {"epsilon", r.epsilon},
                                        {"nanoseconds_per_ray", r.nanoseconds_per_ray},
                                        {"acne", r.acne},
                                        {"leaks", r.leaks},
                                        {"decided", r.decided}});
    }
    return json;
}

std::vector<ParetoFamily> pareto_families_from_json(const nlohmann::json& json) {
    std::vector<ParetoFamily> families;
    for (const nlohmann::json& f : json.at("families")) {
        ParetoFamily family;
        family.name = f.at("name").get<std::string>();
        family.description = f.at("description").get<std::string>();
        family.cases = f.at("cases").get<std::size_t>();
        for (const nlohmann::json& p : f.at("points")) {
            ParetoPoint point;
            point.label = p.at("label").get<std::string>();
            point.precision = p.at("precision").get<std::string>();
            point.function = p.at("function").get<std::string>();
            point.cases = p.at("cases").get<std::size_t>();
            point.false_hits = p.at("false_hits").get<std::size_t>();
            point.false_misses = p.at("false_misses").get<std::size_t>();
            point.t_ulps_median = p.at("t_ulps").at("median").get<double>();
            point.t_ulps_p99 = p.at("t_ulps").at("p99").get<double>();
            point.t_ulps_max = p.at("t_ulps").at("max").get<double>();
            point.mrays_per_second = p.at("mrays_per_second").get<double>();
            family.points.push_back(point);
        }
        families.push_back(family);
    }
    return families;
}

}  // namespace raystep
