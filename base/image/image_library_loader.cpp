#include "base/image/image_library_loader.h"

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX  // keep std::min and std::max usable after windows.h
#endif
#include <windows.h>
#else
#include <dlfcn.h>
#endif
#ifdef __APPLE__
#include <mach-o/dyld.h>
#endif

namespace raystep {

namespace fs = std::filesystem;

namespace {

// The module's table entry, or the reason it could not be had from `path`.
struct Opened {
    RaystepImageLibraryEntry entry = nullptr;
    std::string failure;
};

#ifdef _WIN32

std::string last_system_error() {
    char* text = nullptr;
    const DWORD code = GetLastError();
    FormatMessageA(
        FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS,
        nullptr, code, 0, reinterpret_cast<char*>(&text), 0, nullptr);
    std::string message = text ? text : "error " + std::to_string(code);
    LocalFree(text);
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r'))
        message.pop_back();
    return message;
}

Opened open_module(const fs::path& path) {
    // Loaded for the rest of the process: OpenImageIO keeps threads and caches that outlive any
    // one call, so the module is never unloaded.
    HMODULE module = LoadLibraryW(path.wstring().c_str());
    if (!module) return {nullptr, last_system_error()};
    FARPROC symbol = GetProcAddress(module, RAYSTEP_IMAGE_LIBRARY_SYMBOL);
    if (!symbol) return {nullptr, last_system_error()};
    // Through void (*)(), the function pointer type that converts to any other without a
    // warning (GCC's -Wcast-function-type): FARPROC's own signature is not the entry's.
    return {reinterpret_cast<RaystepImageLibraryEntry>(reinterpret_cast<void (*)()>(symbol)), {}};
}

fs::path executable_path() {
    std::vector<wchar_t> name(32768);
    const DWORD length = GetModuleFileNameW(nullptr, name.data(), static_cast<DWORD>(name.size()));
    return length == 0 ? fs::path() : fs::path(std::wstring(name.data(), length));
}

#else

Opened open_module(const fs::path& path) {
    // Loaded for the rest of the process (never dlclose'd): OpenImageIO keeps threads and caches
    // that outlive any one call. Bound lazily, as a program that links OpenImageIO binds it:
    // binding every function of its libraries up front (RTLD_NOW) slows each render's first
    // image measurably (docs/measurements/startup.md). A missing library still fails here.
    void* module = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!module) {
        // glibc names the file in some of its messages; the caller names it once already
        std::string reason = dlerror();
        const std::string named = path.string() + ": ";
        if (reason.compare(0, named.size(), named) == 0) reason.erase(0, named.size());
        return {nullptr, reason};
    }
    void* symbol = dlsym(module, RAYSTEP_IMAGE_LIBRARY_SYMBOL);
    if (!symbol) return {nullptr, dlerror()};
    return {reinterpret_cast<RaystepImageLibraryEntry>(symbol), {}};
}

fs::path executable_path() {
#ifdef __APPLE__
    uint32_t size = 0;
    _NSGetExecutablePath(nullptr, &size);
    std::vector<char> name(size + 1, '\0');
    if (_NSGetExecutablePath(name.data(), &size) != 0) return {};
    return fs::path(name.data());
#else
    std::error_code error;
    const fs::path path = fs::read_symlink("/proc/self/exe", error);
    return error ? fs::path() : path;
#endif
}

#endif

// The module use_image_library_module named; empty where none was.
fs::path& chosen_module() {
    static fs::path module;
    return module;
}

// Where the module may be: where the program was told, and nowhere else (a grader's probe loads
// no module it was not given); else where this build put it, then beside the executable (a build
// folder moved or installed elsewhere keeps the two together).
std::vector<fs::path> module_candidates() {
    if (!chosen_module().empty()) return {chosen_module()};
    std::vector<fs::path> candidates = {fs::path(RAYSTEP_IMAGE_LIBRARY_PATH)};
    const fs::path executable = executable_path();
    if (!executable.empty()) {
        const fs::path beside = executable.parent_path() / RAYSTEP_IMAGE_LIBRARY_FILE;
        if (beside != candidates.front()) candidates.push_back(beside);
    }
    return candidates;
}

}  // namespace

void use_image_library_module(const fs::path& module) {
    chosen_module() = module;
}

const RaystepImageLibraryTable& load_image_library(const std::vector<fs::path>& candidates) {
    std::string tried;
    for (const fs::path& path : candidates) {
        const Opened opened = open_module(path);
        if (!opened.entry) {
            tried += "\n  " + path.string() + ": " + opened.failure;
            continue;
        }
        const RaystepImageLibraryTable* table = opened.entry();
        if (!table || table->version != RAYSTEP_IMAGE_LIBRARY_VERSION) {
            tried += "\n  " + path.string() + ": built for another version of raystep";
            continue;
        }
        return *table;
    }
    throw std::runtime_error("cannot load the image library (OpenImageIO) from:" + tried);
}

const RaystepImageLibraryTable& image_library() {
    static std::mutex mutex;
    static const RaystepImageLibraryTable* table = nullptr;
    const std::lock_guard<std::mutex> lock(mutex);
    if (!table) table = &load_image_library(module_candidates());
    return *table;
}

void throw_on_image_failure(const char* failure, const std::string& what) {
    if (failure) throw std::runtime_error(what + failure);
}

}  // namespace raystep
