#include "base/scene/scene_loader.h"

#include <functional>

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

// The dialect is the whole file's, whichever line names the integrator: a material written above
// `integrator direct` takes the CSE168 defaults too. A malformed `integrator` line is left to the
// parser, which names what is wrong with it.
SceneDialect dialect_of(std::string_view text) {
    SceneDialect dialect = SceneDialect::cse167;
    std::vector<std::string_view> fields;
    for_each_line(text, [&](const std::string& line) {
        split_fields(line, fields);
        if (fields.size() == 2 && fields[0] == "integrator" &&
            (fields[1] == "direct" || fields[1] == "analyticdirect" || fields[1] == "pathtracer")) {
            dialect = SceneDialect::cse168;
        }
    });
    return dialect;
}

}  // namespace

Scene parse_scene(std::string_view text, const std::string& name,
                  const std::filesystem::path& folder) {
    scene_parsing::SceneParser parser(name, folder, dialect_of(text));
    for_each_line(text, [&](const std::string& line) { parser.parse_line(line); });
    return parser.finish();
}

Scene load_scene(const std::filesystem::path& path) {
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
    return parse_scene(read_text_file(path, "scene file"), path.string(), folder);
}

}  // namespace raystep
