#include "grader/grade/release_grading.h"

#include <fstream>

#include "app/grade/public_case.h"
#include "grader/grade/checks/data_judged.h"
#include "grading/3_intersect/case_file_judges.h"

namespace raystep::grade {

std::size_t write_release_grading(const std::filesystem::path& source,
                                  const std::filesystem::path& rubric,
                                  const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder);
    std::filesystem::copy_file(rubric, folder / "rubric.json",
                               std::filesystem::copy_options::overwrite_existing);
    // What the reference gets right of stage 3's public case files, which a student's function
    // must match (grading/3_intersect/case_file_judges.h).
    std::ofstream(folder / "stage3-reference.json")
        << probe::Json(stage3_cases_right(stage3_public_families(source))) << "\n";
    std::size_t written = 0;
    for (const PublicCheck& check : public_checks(source)) {
        write_public_check(check, folder / "public");
        ++written;
    }
    return written;
}

}  // namespace raystep::grade
