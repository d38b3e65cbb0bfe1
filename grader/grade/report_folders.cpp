#include "grader/grade/report_folders.h"

namespace raystep::grade {

std::filesystem::path student_folder(const std::filesystem::path& output) {
    return output / "student";
}

std::filesystem::path instructor_folder(const std::filesystem::path& output) {
    return output / "instructor";
}

std::filesystem::path finished_report_file(const std::filesystem::path& output) {
    return instructor_folder(output) / "report.json";
}

}  // namespace raystep::grade
