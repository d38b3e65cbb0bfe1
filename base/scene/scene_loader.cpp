#include "base/scene/scene_loader.h"

#include "base/scene/scene_parser.h"
#include "base/scene/text_file.h"

namespace raystep {

Scene parse_scene(std::string_view text, const std::string& name,
                  const std::filesystem::path& folder) {
    scene_parsing::SceneParser parser(name, folder);
    std::string line;
    std::size_t start = 0;
    while (start < text.size()) {
        // A line ends at "\n", "\r\n" or a lone "\r" (old Mac files).
        std::size_t end = text.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = text.size();
        // A copy per line keeps each field NUL- or space-terminated for strtod.
        line.assign(text.substr(start, end - start));
        parser.parse_line(line);
        start = end + 1;
        if (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n') ++start;
    }
    return parser.finish();
}

Scene load_scene(const std::filesystem::path& path) {
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
    return parse_scene(read_text_file(path, "scene file"), path.string(), folder);
}

}  // namespace raystep
