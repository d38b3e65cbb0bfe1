#include "grader/grade/object_cache.h"

#include <stdlib.h>  // mkdtemp

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "grader/grade/sandbox_copies.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

std::string read_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string hex(std::size_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016zx", value);
    return text;
}

// Each file under `folder` by its path relative to it, in order, with its bytes.
std::string folder_bytes(const fs::path& folder) {
    std::vector<fs::path> paths;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder)) {
        if (entry.is_regular_file()) paths.push_back(entry.path());
    }
    std::sort(paths.begin(), paths.end());
    std::string bytes;
    for (const fs::path& path : paths) {
        const std::string content = read_bytes(path);
        bytes += "\n" + fs::relative(path, folder).generic_string() + " " +
                 std::to_string(content.size()) + "\n" + content;
    }
    return bytes;
}

// The files a make rule written by the compiler's -MD names after its target, unescaped.
std::vector<fs::path> dependencies_in(const std::string& rule) {
    const std::size_t colon = rule.find(": ");
    if (colon == std::string::npos) throw std::runtime_error("no make rule");
    std::vector<fs::path> files;
    std::string word;
    const auto end_word = [&] {
        if (!word.empty()) files.emplace_back(word);
        word.clear();
    };
    for (std::size_t k = colon + 1; k < rule.size(); ++k) {
        const char c = rule[k];
        if (c == '\\' && k + 1 < rule.size() && rule[k + 1] == '\n') {
            ++k;
            end_word();
        } else if (c == '\\' && k + 1 < rule.size() && (rule[k + 1] == ' ' || rule[k + 1] == '#')) {
            word += rule[++k];
        } else if (c == '$' && k + 1 < rule.size() && rule[k + 1] == '$') {
            word += rule[++k];
        } else if (c == ' ' || c == '\t' || c == '\n') {
            end_word();
        } else {
            word += c;
        }
    }
    end_word();
    return files;
}

bool is_under(const fs::path& path, const fs::path& folder) {
    const fs::path relative = path.lexically_relative(folder);
    return !relative.empty() && *relative.begin() != "..";
}

}  // namespace

ObjectCache::ObjectCache(fs::path folder, const ProbeToolchain& toolchain, fs::path work)
    : folder_(std::move(folder)), work_(std::move(work)) {
    fs::create_directories(folder_);
    const fs::path compiler = fs::canonical(toolchain.compiler);
    toolchain_inputs_ = "compiler " + compiler.string() + " " +
                        std::to_string(fs::file_size(compiler)) + " " +
                        std::to_string(fs::last_write_time(compiler).time_since_epoch().count());
    for (const std::string& flag : toolchain.compile_flags)
        toolchain_inputs_ += " " + flag;
    // The precompiled header (work/precompiled, from the build tree) by the build's file, whose
    // size and time move with every rebuild of it: it is the grader's, like the headers.
    if (!toolchain.precompiled_header.empty()) {
        const fs::path compiled = toolchain.precompiled_header.string() + ".gch";
        std::error_code none;
        toolchain_inputs_ +=
            "\nprecompiled " + compiled.string() + " " +
            std::to_string(fs::file_size(compiled, none)) + " " +
            std::to_string(fs::last_write_time(compiled, none).time_since_epoch().count());
    }
    // The headers are the grader's own, so a hash that only finds them is enough here.
    toolchain_inputs_ +=
        "\nheaders " + hex(std::hash<std::string>{}(folder_bytes(work_ / "include")));
}

std::vector<std::string> ObjectCache::dependency_flags(const fs::path& object) {
    return {"-MD", "-MF", fs::path(object).replace_extension(".d").string()};
}

std::string ObjectCache::inputs(const fs::path& source) const {
    const std::string bytes = read_bytes(source);
    return toolchain_inputs_ + "\ncompiled " + source.filename().string() + " " +
           std::to_string(bytes.size()) + "\n" + bytes;
}

fs::path ObjectCache::entry(const std::string& inputs) const {
    return folder_ / hex(std::hash<std::string>{}(inputs));
}

// A file of the work folder ("@/submission/...") byte for byte; any other (the system's headers,
// which no student writes) by its size and time.
std::string ObjectCache::fingerprint(const std::vector<std::string>& read) const {
    std::string text;
    for (const std::string& file : read) {
        if (file.rfind("@/", 0) == 0) {
            const std::string bytes = read_bytes(work_ / file.substr(2));
            text += file + " " + std::to_string(bytes.size()) + "\n" + bytes + "\n";
        } else {
            text += file + " " + std::to_string(fs::file_size(file)) + " " +
                    std::to_string(fs::last_write_time(file).time_since_epoch().count()) + "\n";
        }
    }
    return text;
}

bool ObjectCache::take(const fs::path& source, const fs::path& object) const {
    try {
        const std::string wanted = inputs(source);
        const fs::path found = entry(wanted);
        if (!fs::is_regular_file(found / "object.o") || read_bytes(found / "inputs") != wanted)
            return false;
        std::vector<std::string> read;
        std::istringstream list(read_bytes(found / "read"));
        for (std::string line; std::getline(list, line);)
            read.push_back(line);
        if (fingerprint(read) != read_bytes(found / "fingerprint")) return false;
        copy_file_for_sandbox(found / "object.o", object, kSharedFile);
        return true;
    } catch (const std::exception&) {
        // A cache that cannot be read only costs a compile.
        std::error_code ignored;
        fs::remove(object, ignored);
        return false;
    }
}

void ObjectCache::keep(const fs::path& source, const fs::path& object) const {
    std::string aside = (folder_ / "new-XXXXXX").string();
    if (mkdtemp(aside.data()) == nullptr) return;
    try {
        // What the compile read besides the file and the headers, as the entry names it.
        std::vector<std::string> read;
        std::string list;
        const fs::path rule = fs::path(object).replace_extension(".d");
        for (const fs::path& file : dependencies_in(read_bytes(rule))) {
            const fs::path path = fs::absolute(file).lexically_normal();
            if (path == source.lexically_normal() || is_under(path, work_ / "include") ||
                is_under(path, work_ / "precompiled")) {
                continue;
            }
            read.push_back(is_under(path, work_)
                               ? "@/" + path.lexically_relative(work_).generic_string()
                               : path.string());
            list += read.back() + "\n";
        }
        const std::string kept = inputs(source);
        std::ofstream(fs::path(aside) / "inputs", std::ios::binary) << kept;
        std::ofstream(fs::path(aside) / "read", std::ios::binary) << list;
        std::ofstream(fs::path(aside) / "fingerprint", std::ios::binary) << fingerprint(read);
        copy_file_for_sandbox(object, fs::path(aside) / "object.o", kSharedFile);
        // Fails when another grader kept the entry first, or one of the same hash: either stays.
        std::error_code taken;
        fs::rename(aside, entry(kept), taken);
        if (!taken) return;
    } catch (const std::exception&) {
        // A cache that cannot be written only costs a compile next time.
    }
    std::error_code ignored;
    fs::remove_all(aside, ignored);
}

}  // namespace raystep::grade
