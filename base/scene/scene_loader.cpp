#include "base/scene/scene_loader.h"

#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "base/scene/scene_parser.h"
#include "base/scene/text_fields.h"
#include "base/scene/text_file.h"

namespace raystep {

namespace {

// Calls `read` on each line of `text`. A line ends at "\n", "\r\n" or a lone "\r" (old Mac
// files), and is handed over as a string of its own, which keeps each field NUL- or
// space-terminated for strtod.
void for_each_line(std::string_view text, const std::function<void(const std::string&)>& read) {
    std::string line;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = text.size();
        line.assign(text.substr(start, end - start));
        read(line);
        start = end + 1;
        if (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n') ++start;
    }
}

// The integrator, and with it the dialect, is the whole file's, whichever line names it: a
// material written above `integrator direct` takes the CSE168 defaults too. That line is read
// first, by a parser of its own, so that a malformed one is reported as itself rather than
// through what the dialect it failed to set makes of an earlier line (a `maxdepth -1` above
// `integrator pathtracing`).
Integrator integrator_of(std::string_view text, const std::string& name,
                         const std::filesystem::path& folder) {
    int number = 0;
    std::optional<std::pair<int, std::string>> integrator;
    std::vector<std::string_view> fields;
    for_each_line(text, [&](const std::string& line) {
        ++number;
        split_fields(line, fields);
        if (!integrator && !fields.empty() && fields[0] == "integrator") {
            integrator.emplace(number, line);
        }
    });
    if (!integrator) return Integrator::raytracer;
    scene_parsing::SceneParser scratch(name, folder, Integrator::raytracer);
    scratch.parse_line_at(integrator->first, integrator->second);
    return scratch.scene_integrator();
}

}  // namespace

Scene parse_scene(std::string_view text, const std::string& name,
                  const std::filesystem::path& folder) {
    scene_parsing::SceneParser parser(name, folder, integrator_of(text, name, folder));
    for_each_line(text, [&](const std::string& line) { parser.parse_line(line); });
    return parser.finish();
}

Scene load_scene(const std::filesystem::path& path) {
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
    return parse_scene(read_text_file(path, "scene file"), path.string(), folder);
}

}  // namespace raystep
