#include "app/view/file_stamps.h"

#include <system_error>

namespace raystep {

namespace {

std::string file_stamp(const std::filesystem::path& file) {
    std::error_code error;
    const auto time = std::filesystem::last_write_time(file, error);
    if (error) return "missing";
    const auto size = std::filesystem::file_size(file, error);
    if (error) return "missing";
    // libc++ counts file time in __int128, which std::to_string does not take; nanoseconds
    // since 1970 fit a long long until 2262.
    return std::to_string(static_cast<long long>(time.time_since_epoch().count())) + " " +
           std::to_string(size);
}

}  // namespace

FileStamps::FileStamps(std::vector<std::filesystem::path> files) : files_(std::move(files)) {
    for (const std::filesystem::path& file : files_)
        stamps_.push_back(file_stamp(file));
}

bool FileStamps::changed() const {
    for (std::size_t k = 0; k < files_.size(); ++k) {
        if (file_stamp(files_[k]) != stamps_[k]) return true;
    }
    return false;
}

}  // namespace raystep
