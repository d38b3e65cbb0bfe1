#pragma once

#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>

namespace raystep::testing {

/// A new, empty folder under the system's temporary folder for one test case, removed after it.
/// ctest runs test cases of one executable as parallel processes, and other builds on the machine
/// run the same tests: a fixed name lets one case read a file another is rewriting. The name is
/// random and create_directory fails when it exists, so the folder is this case's alone.
class ScratchFolder {
  public:
    explicit ScratchFolder(const std::string& purpose) {
        std::random_device entropy;
        for (int attempt = 0; attempt < 100; ++attempt) {
            path_ = std::filesystem::temp_directory_path() /
                    ("raystep-" + purpose + "-" + std::to_string(entropy()));
            if (std::filesystem::create_directory(path_)) return;
        }
        throw std::runtime_error("cannot create a scratch folder for " + purpose);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

}  // namespace raystep::testing
