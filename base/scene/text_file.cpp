#include "base/scene/text_file.h"

#include <fstream>
#include <sstream>

#include "base/errors/input_error.h"

namespace raystep {

std::string read_text_file(const std::filesystem::path& path, const std::string& what) {
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        throw InputError(path.string(), 0, what + " not found");
    if (!std::filesystem::is_regular_file(path, error)) {
        throw InputError(path.string(), 0, "not a regular file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string(), 0, "cannot read the " + what);
    std::ostringstream contents;
    contents << in.rdbuf();
    return contents.str();
}

}  // namespace raystep
