#pragma once

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

namespace raystep::grade {

/// One entry of a submission as raystep-unpack lists it, an archive's or a folder's: its path
/// inside the submission (a name only, never handed to the file system), its kind ("file",
/// "folder", "link", "other"), its size (-1 where unknown), whether its contents were taken, and
/// for a link what it points to (read, never followed). Printed as one JSON line on stdout, with
/// bytes that are not UTF-8 replaced.
inline void print_entry(const std::string& path, const std::string& kind, long long size,
                        bool taken, const std::string& link_target = "") {
    nlohmann::json line = {{"path", path}, {"kind", kind}, {"size", size}, {"taken", taken}};
    if (kind == "link") line["target"] = link_target;
    std::puts(line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
}

}  // namespace raystep::grade
