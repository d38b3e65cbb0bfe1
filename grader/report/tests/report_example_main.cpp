// raystep_report_example: the example grade (report_example.h) for looking at the reports and for
// the HTML report's browser test (html_screenshot_test.py).
//
//   raystep_report_example write FOLDER             every report of the example into FOLDER,
//                                                   in FOLDER/student and FOLDER/instructor
//   raystep_report_example check-screenshot PNG     exit 0 when a screenshot of the HTML report
//                                                   shows a page with the example's images
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <set>
#include <string>
#include <tuple>

#include "app/report/console_summary.h"
#include "base/image/image.h"
#include "base/image/image_io.h"
#include "grader/grade/write_reports.h"
#include "report_example.h"

namespace {

using namespace raystep;

void write_text(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error(file.string() + ": cannot write");
}

// Every report of the example, as raystep-grade lays them out (report_folders.h), the images
// where render checks write them; the console's two views beside.
void write_reports(const std::filesystem::path& folder) {
    const grade::GradeReport report = testing::example_report();
    testing::write_example_images(grade::instructor_folder(folder));
    grade::write_reports(report, folder);
    write_text(folder / "console-instructor.txt",
               grade::console_summary(report, grade::Audience::instructor));
    write_text(folder / "console-student.txt",
               grade::console_summary(report, grade::Audience::student));
}

// A screenshot of the report shows a page when it is not one colour, and shows the example's
// images when it has a good area of their marker colour: a broken image would show an icon.
bool screenshot_shows_report(const std::filesystem::path& png) {
    const Image image = read_image(png);
    // 8-bit PNG read back as floats: within 6 of 255 per channel allows for colour management.
    constexpr double kTolerance = 6.0 / 255.0;
    // The example's disc is 18 pixels wide, drawn about 7 times larger: thousands of pixels in
    // each of two images. A few hundred rule out chance matches in the page's own colours.
    constexpr int kMinMarkerPixels = 400;
    std::set<std::tuple<int, int, int>> colours;
    int marker = 0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            const Color c = image.at(i, j);
            if (colours.size() < 64) {
                colours.insert({static_cast<int>(c.r * 255), static_cast<int>(c.g * 255),
                                static_cast<int>(c.b * 255)});
            }
            const bool is_marker = std::abs(c.r - testing::kMarker[0] / 255.0) < kTolerance &&
                                   std::abs(c.g - testing::kMarker[1] / 255.0) < kTolerance &&
                                   std::abs(c.b - testing::kMarker[2] / 255.0) < kTolerance;
            if (is_marker) ++marker;
        }
    }
    std::printf("%s: %d x %d, %s%zu colours, %d pixels of the images' marker colour\n",
                png.string().c_str(), image.width(), image.height(),
                colours.size() == 64 ? "at least " : "", colours.size(), marker);
    return colours.size() > 1 && marker >= kMinMarkerPixels;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string command = argc == 3 ? argv[1] : "";
    try {
        if (command == "write") {
            write_reports(argv[2]);
            return EXIT_SUCCESS;
        }
        if (command == "check-screenshot") {
            return screenshot_shows_report(argv[2]) ? EXIT_SUCCESS : EXIT_FAILURE;
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "raystep_report_example: %s\n", error.what());
        return EXIT_FAILURE;
    }
    std::fprintf(stderr,
                 "usage: raystep_report_example write FOLDER\n"
                 "       raystep_report_example check-screenshot PNG\n");
    return 2;
}
