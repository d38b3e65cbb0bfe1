#include "renderer/progress_bar.h"

#include <cstdio>
#include <string>

#include "base/testing/catch.h"

using namespace raystep;

namespace {

// Everything written to `file` so far.
std::string contents(std::FILE* file) {
    std::fflush(file);
    std::rewind(file);
    std::string text;
    for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file))
        text += static_cast<char>(c);
    return text;
}

}  // namespace

TEST_CASE("ProgressBar: with a unit, the bar counts what is done of the total", "[app]") {
    std::FILE* file = std::tmpfile();
    REQUIRE(file);
    ProgressBar bar("scene.png", 64, true, file, "samples");
    bar.update(16);
    const std::string text = contents(file);
    CHECK(text.find(" 25%") != std::string::npos);
    CHECK(text.find("16 of 64 samples") != std::string::npos);
    std::fclose(file);
}

TEST_CASE("ProgressBar: without a unit, only the share and the time", "[app]") {
    std::FILE* file = std::tmpfile();
    REQUIRE(file);
    ProgressBar bar("scene.png", 64, true, file);
    bar.update(16);
    CHECK(contents(file).find(" of ") == std::string::npos);
    std::fclose(file);
}
