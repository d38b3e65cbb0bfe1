#include "grader/grade/report_json.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "grader/grade/report_folders.h"

namespace raystep::grade {

namespace {

Outcome outcome_from(const std::string& name) {
    for (const Outcome o : {Outcome::passed, Outcome::failed, Outcome::crashed, Outcome::timed_out,
                            Outcome::not_implemented, Outcome::did_not_compile}) {
        if (outcome_name(o) == name) return o;
    }
    throw std::invalid_argument("unknown outcome " + name);
}

// JSON has no infinity (a PSNR of identical images is one): non-finite values go as strings.
nlohmann::json metrics_json(const std::map<std::string, double>& metrics) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, value] : metrics) {
        if (std::isfinite(value)) {
            j[name] = value;
        } else {
            j[name] = std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
        }
    }
    return j;
}

std::map<std::string, double> metrics_from(const nlohmann::json& j) {
    std::map<std::string, double> metrics;
    for (const auto& [name, value] : j.items()) {
        if (value.is_number()) {
            metrics[name] = value.get<double>();
        } else {
            const std::string text = value.get<std::string>();
            metrics[name] = text == "inf" ? HUGE_VAL : text == "-inf" ? -HUGE_VAL : std::nan("");
        }
    }
    return metrics;
}

Visibility visibility_from(const std::string& name) {
    for (const Visibility v : {Visibility::visible, Visibility::hidden, Visibility::after_due_date,
                               Visibility::after_published}) {
        if (visibility_name(v) == name) return v;
    }
    throw std::invalid_argument("unknown visibility " + name);
}

}  // namespace

nlohmann::json report_json(const GradeReport& report) {
    nlohmann::json checks = nlohmann::json::array();
    for (const CheckResult& c : report.checks) {
        nlohmann::json counterexamples = nlohmann::json::array();
        for (const Counterexample& x : c.counterexamples) {
            counterexamples.push_back({{"input", x.input},
                                       {"expected", x.expected},
                                       {"got", x.got},
                                       {"reproduce", x.reproduce},
                                       {"student_reproduce", x.student_reproduce}});
        }
        checks.push_back({{"id", c.id},
                          {"stage", c.stage},
                          {"kind", c.kind},
                          {"name", c.name},
                          {"outcome", outcome_name(c.outcome)},
                          {"score", c.score},
                          {"max_score", c.max_score},
                          {"visibility", visibility_name(c.visibility)},
                          {"summary", c.summary},
                          {"counterexamples", counterexamples},
                          {"metrics", metrics_json(c.metrics)},
                          {"images",
                           {{"reference", c.images.reference},
                            {"student", c.images.student},
                            {"difference", c.images.difference}}},
                          {"details", c.details},
                          {"seconds", c.seconds}});
    }
    return {{"submission", report.submission},
            {"student", report.student},
            {"intake_problem", report.intake_problem},
            {"work_folder", report.work_folder},
            {"score", report.score()},
            {"max_score", report.max_score()},
            {"times",
             {{"intake", report.times.intake},
              {"build", report.times.build},
              {"checks", report.times.checks},
              {"reports", report.times.reports}}},
            {"checks", checks}};
}

GradeReport report_from_json(const nlohmann::json& j) {
    GradeReport report;
    report.submission = j.at("submission").get<std::string>();
    report.student = j.at("student").get<std::string>();
    report.intake_problem = j.value("intake_problem", "");
    report.work_folder = j.value("work_folder", "");
    const nlohmann::json& times = j.at("times");
    report.times = {times.at("intake").get<double>(), times.at("build").get<double>(),
                    times.at("checks").get<double>(), times.at("reports").get<double>()};
    for (const nlohmann::json& c : j.at("checks")) {
        CheckResult check;
        check.id = c.at("id").get<std::string>();
        check.stage = c.at("stage").get<int>();
        check.kind = c.at("kind").get<std::string>();
        check.name = c.at("name").get<std::string>();
        check.outcome = outcome_from(c.at("outcome").get<std::string>());
        check.score = c.at("score").get<double>();
        check.max_score = c.at("max_score").get<double>();
        check.visibility = visibility_from(c.at("visibility").get<std::string>());
        check.summary = c.at("summary").get<std::string>();
        for (const nlohmann::json& x : c.at("counterexamples")) {
            check.counterexamples.push_back(
                {x.at("input").get<std::string>(), x.at("expected").get<std::string>(),
                 x.at("got").get<std::string>(), x.at("reproduce").get<std::string>(),
                 x.value("student_reproduce", "")});
        }
        check.metrics = metrics_from(c.at("metrics"));
        const nlohmann::json& images = c.at("images");
        check.images = {images.at("reference").get<std::string>(),
                        images.at("student").get<std::string>(),
                        images.at("difference").get<std::string>()};
        check.details = c.at("details").get<std::string>();
        check.seconds = c.value("seconds", 0.0);
        report.checks.push_back(std::move(check));
    }
    return report;
}

std::optional<GradeReport> finished_report(const std::filesystem::path& output) {
    std::ifstream in(finished_report_file(output));
    if (!in) return std::nullopt;
    try {
        return report_from_json(nlohmann::json::parse(in));
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

}  // namespace raystep::grade
