#include "grader/grade/release_grading.h"

#include "app/grade/public_case.h"
#include "grader/grade/checks/data_judged.h"

namespace raystep::grade {

std::size_t write_release_grading(const std::filesystem::path& source,
                                  const std::filesystem::path& rubric,
                                  const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder);
    std::filesystem::copy_file(rubric, folder / "rubric.json",
                               std::filesystem::copy_options::overwrite_existing);
    std::size_t written = 0;
    for (const PublicCheck& check : public_checks(source)) {
        write_public_check(check, folder / "public");
        ++written;
    }
    return written;
}

}  // namespace raystep::grade
