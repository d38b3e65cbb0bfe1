#include "grader/grade/checks/kept_renders.h"

#include <stdlib.h>  // mkstemp
#include <unistd.h>  // close

#include <cstdio>
#include <fstream>
#include <functional>
#include <system_error>

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

fs::path entry(const fs::path& folder, const std::string& key) {
    char name[32];
    std::snprintf(name, sizeof name, "%016zx.renders", std::hash<std::string>{}(key));
    return folder / name;
}

}  // namespace

std::optional<std::vector<Image>> kept_renders(const fs::path& folder, const std::string& key) {
    std::ifstream in(entry(folder, key), std::ios::binary);
    std::string kept_key(key.size(), '\0');
    if (!in.read(kept_key.data(), static_cast<std::streamsize>(key.size())) || kept_key != key)
        return std::nullopt;
    std::uint32_t count = 0;
    if (!in.read(reinterpret_cast<char*>(&count), sizeof count)) return std::nullopt;
    std::vector<Image> renders;
    for (std::uint32_t k = 0; k < count; ++k) {
        std::int32_t size[2] = {0, 0};
        if (!in.read(reinterpret_cast<char*>(size), sizeof size) || size[0] <= 0 || size[1] <= 0 ||
            size[0] > 1 << 14 || size[1] > 1 << 14)
            return std::nullopt;
        Image image(size[0], size[1]);
        const std::streamsize bytes = std::streamsize{3} * size[0] * size[1] * sizeof(float);
        if (!in.read(reinterpret_cast<char*>(image.data()), bytes)) return std::nullopt;
        renders.push_back(std::move(image));
    }
    if (in.peek() != std::char_traits<char>::eof()) return std::nullopt;
    return renders;
}

void keep_renders(const fs::path& folder, const std::string& key,
                  const std::vector<Image>& renders) {
    std::error_code error;
    fs::create_directories(folder, error);
    std::string aside = (folder / "new-XXXXXX").string();
    const int descriptor = mkstemp(aside.data());
    if (descriptor < 0) return;
    close(descriptor);
    {
        std::ofstream out(aside, std::ios::binary | std::ios::trunc);
        out.write(key.data(), static_cast<std::streamsize>(key.size()));
        const auto count = static_cast<std::uint32_t>(renders.size());
        out.write(reinterpret_cast<const char*>(&count), sizeof count);
        for (const Image& image : renders) {
            const std::int32_t size[2] = {image.width(), image.height()};
            out.write(reinterpret_cast<const char*>(size), sizeof size);
            out.write(reinterpret_cast<const char*>(image.data()),
                      std::streamsize{3} * image.width() * image.height() * sizeof(float));
        }
        if (out) {
            out.close();
            fs::rename(aside, entry(folder, key), error);
            if (!error) return;
        }
    }
    fs::remove(aside, error);
}

std::string grader_identity() {
    std::error_code error;
    const fs::path program = fs::canonical("/proc/self/exe", error);
    if (error) return "";
    const std::uintmax_t size = fs::file_size(program, error);
    if (error) return "";
    const fs::file_time_type time = fs::last_write_time(program, error);
    if (error) return "";
    return program.string() + " " + std::to_string(size) + " " +
           std::to_string(time.time_since_epoch().count());
}

}  // namespace raystep::grade
