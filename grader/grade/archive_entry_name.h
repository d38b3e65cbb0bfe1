#pragma once

#include <string>

namespace raystep::grade {

/// The file name of a submission's entry, as its path names it ("stages/3_intersect/sphere.cpp"
/// -> "sphere.cpp"): the part after the last '/' or '\\', trailing ones ignored. raystep-unpack
/// takes an archive's entries by it and raystep-grade chooses among them by it, so both use this
/// one rule. A string only: the path is never handed to the file system.
inline std::string archive_entry_name(const std::string& path) {
    std::string trimmed = path;
    while (!trimmed.empty() && (trimmed.back() == '/' || trimmed.back() == '\\'))
        trimmed.pop_back();
    const std::size_t slash = trimmed.find_last_of("/\\");
    return slash == std::string::npos ? trimmed : trimmed.substr(slash + 1);
}

}  // namespace raystep::grade
