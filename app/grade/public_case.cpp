#include "app/grade/public_case.h"

#include <fstream>
#include <sstream>

#include "app/grade/data_judge.h"
#include "base/errors/input_error.h"

namespace raystep::grade {

namespace {

using probe::Json;

// The header takes the first line, and case k the line 2 + k.
constexpr int kFirstCaseLine = 2;

std::string dumped(const Json& j) {
    return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

Json case_json(const PublicCase& c) {
    return {{"input", c.input},
            {"call", c.query.call},
            {"args", c.query.args},
            {"judge", c.judge},
            {"reproduce", c.reproduce}};
}

PublicCase case_from(const Json& j) {
    PublicCase c;
    c.input = j.at("input").get<std::string>();
    c.query = {j.at("call").get<std::string>(), j.at("args")};
    c.judge = j.at("judge");
    c.reproduce = j.at("reproduce").get<std::string>();
    build_judge(c.judge);  // a judge this build cannot build is the file's fault, said here
    return c;
}

// The line of the byte at `offset` (from 1).
int line_at(const std::string& text, std::size_t offset) {
    int line = 1;
    for (std::size_t k = 0; k < offset && k < text.size(); ++k) {
        if (text[k] == '\n') ++line;
    }
    return line;
}

}  // namespace

std::string public_check_text(const PublicCheck& check) {
    const Json header = {
        {"check", check.id}, {"stage", check.stage}, {"kind", check.kind}, {"name", check.name}};
    std::string text = dumped(header);
    text.pop_back();  // the closing brace: the cases follow on lines of their own
    text += ", \"cases\": [\n";
    for (std::size_t k = 0; k < check.cases.size(); ++k) {
        text += dumped(case_json(check.cases[k]));
        text += k + 1 < check.cases.size() ? ",\n" : "\n";
    }
    text += "]}\n";
    return text;
}

void write_public_check(const PublicCheck& check, const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder);
    const std::filesystem::path file = folder / (check.id + ".json");
    std::ofstream out(file);
    out << public_check_text(check);
    if (!out) throw std::runtime_error(file.string() + ": cannot be written");
}

PublicCheck read_public_check(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw InputError(file.string(), 0, "cannot be read");
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    Json j;
    try {
        j = Json::parse(text);
    } catch (const Json::parse_error& error) {
        throw InputError(file.string(), line_at(text, error.byte),
                         "not JSON: " + std::string(error.what()));
    }
    PublicCheck check;
    try {
        check.id = j.at("check").get<std::string>();
        check.stage = j.at("stage").get<int>();
        check.kind = j.at("kind").get<std::string>();
        check.name = j.at("name").get<std::string>();
        j.at("cases").get_ref<const Json::array_t&>();
    } catch (const std::exception& error) {
        throw InputError(file.string(), 1, error.what());
    }
    const Json& cases = j.at("cases");
    for (std::size_t k = 0; k < cases.size(); ++k) {
        try {
            check.cases.push_back(case_from(cases[k]));
        } catch (const std::exception& error) {
            throw InputError(file.string(), kFirstCaseLine + static_cast<int>(k),
                             "case " + std::to_string(k) + ": " + error.what());
        }
    }
    return check;
}

}  // namespace raystep::grade
