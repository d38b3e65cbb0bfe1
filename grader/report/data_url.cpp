#include "grader/report/data_url.h"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "app/protocol/base64.h"

namespace raystep::grade {

namespace {

// The media type a browser needs for an image of this extension; empty for any other.
std::string image_media_type(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".png") return "image/png";
    if (extension == ".jpg" || extension == ".jpeg") return "image/jpeg";
    if (extension == ".gif") return "image/gif";
    return "";
}

}  // namespace

std::optional<std::string> image_data_url(const std::filesystem::path& file,
                                          std::size_t max_bytes) {
    const std::string media_type = image_media_type(file);
    if (media_type.empty()) return std::nullopt;
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(file, error);
    if (error || size > max_bytes) return std::nullopt;
    std::ifstream in(file, std::ios::binary);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    // A file that shrank since its size was read is shown as missing.
    if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()))) return std::nullopt;
    return "data:" + media_type + ";base64," + base64(bytes);
}

}  // namespace raystep::grade
