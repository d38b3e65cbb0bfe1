#include "grader/grade/probe_toolchain.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "grader/grade/build_locations.h"

namespace raystep::grade {

namespace {

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string word; in >> word;)
        out.push_back(word);
    return out;
}

}  // namespace

ProbeToolchain load_probe_toolchain(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in)
        throw std::runtime_error(file.string() + ": missing; configure the grader's build again");
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        ProbeToolchain t;
        t.compiler = j.at("compiler").get<std::string>();
        t.compile_flags = words(j.at("compile_flags").get<std::string>());
        t.precompiled_header = j.at("precompiled_header").get<std::string>();
        for (const auto& o : j.at("probe_objects"))
            t.probe_objects.emplace_back(o.get<std::string>());
        for (const auto& l : j.at("libraries"))
            t.libraries.emplace_back(l.get<std::string>());
        t.link_flags = words(j.at("link_flags").get<std::string>());
        t.nm_plugin = j.at("nm_plugin").get<std::string>();
        t.image_module = j.at("image_module").get<std::string>();
        for (const auto& [stage, library] : j.at("stage_libraries").items()) {
            t.stage_libraries[std::stoi(stage)] = library.get<std::string>();
        }
        t.source = j.at("source").get<std::string>();
        return t;
    } catch (const nlohmann::json::exception& error) {
        throw std::runtime_error(file.string() + ": " + error.what());
    }
}

ProbeToolchain this_build_toolchain() {
    return load_probe_toolchain(built_probe_toolchain());
}

}  // namespace raystep::grade
