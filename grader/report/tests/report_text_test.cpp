#include "app/report/report_text.h"

#include <cmath>
#include <random>

#include <nlohmann/json.hpp>

#include "base/testing/catch.h"
#include "report_example.h"

using namespace raystep::grade;

namespace {

const std::string kFffd = "\xEF\xBF\xBD";

std::string times(int n, const std::string& text) {
    std::string all;
    for (int k = 0; k < n; ++k)
        all += text;
    return all;
}

}  // namespace

TEST_CASE("displayable_text: valid UTF-8, tabs and newlines pass unchanged", "[report]") {
    const std::string text = "plain\ttext\né ∑ 😀 \xF4\x8F\xBF\xBF";  // the last is U+10FFFF
    CHECK(displayable_text(text) == text);
    CHECK(displayable_text("") == "");
}

TEST_CASE("displayable_text: each byte that is not UTF-8 becomes U+FFFD", "[report]") {
    CHECK(displayable_text("a\xFF"
                           "b") == "a" + kFffd + "b");
    CHECK(displayable_text("\x80") == kFffd);                        // stray continuation byte
    CHECK(displayable_text("\xC0\xAF") == times(2, kFffd));          // overlong '/'
    CHECK(displayable_text("\xE0\x80\xAF") == times(3, kFffd));      // overlong, 3 bytes
    CHECK(displayable_text("\xED\xA0\x80") == times(3, kFffd));      // a UTF-16 surrogate
    CHECK(displayable_text("\xF4\x90\x80\x80") == times(4, kFffd));  // past U+10FFFF
    CHECK(displayable_text("x\xE2\x82") == "x" + times(2, kFffd));   // cut short at the end
    CHECK(displayable_text("\xC3(") == kFffd + "(");                 // lead without continuation
}

TEST_CASE("displayable_text: controls, overrides and non-characters become U+FFFD", "[report]") {
    CHECK(displayable_text("\x1b[31mred") == kFffd + "[31mred");       // a terminal escape
    CHECK(displayable_text("fail\rpass") == "fail" + kFffd + "pass");  // would overwrite the line
    CHECK(displayable_text("line\r\nnext") == "line\nnext");
    CHECK(displayable_text(std::string("a\0b", 3)) == "a" + kFffd + "b");
    CHECK(displayable_text("\x7f") == kFffd);
    CHECK(displayable_text("\xC2\x9B") == kFffd);      // C1 CSI
    CHECK(displayable_text("\xE2\x80\xAE") == kFffd);  // right-to-left override
    CHECK(displayable_text("\xE2\x81\xA6") == kFffd);  // left-to-right isolate
    CHECK(displayable_text("\xEF\xBF\xBE") == kFffd);  // U+FFFE
}

TEST_CASE(
    "displayable_text: any bytes give text that JSON accepts, and a second pass changes nothing",
    "[report]") {
    for (unsigned seed = 1; seed <= 200; ++seed) {
        CAPTURE(seed);
        std::mt19937 random(seed);
        std::string bytes(static_cast<std::size_t>(random() % 64), '\0');
        for (char& c : bytes)
            c = static_cast<char>(random() & 0xFF);
        const std::string shown = displayable_text(bytes);
        CHECK(displayable_text(shown) == shown);
        // nlohmann::json refuses invalid UTF-8 when it writes.
        CHECK_NOTHROW(nlohmann::json(shown).dump());
    }
    CHECK_NOTHROW(nlohmann::json(displayable_text(raystep::testing::kHostile)).dump());
}

TEST_CASE("clipped_text: cuts at a character boundary and says how much it cut", "[report]") {
    CHECK(clipped_text("short", 10) == "short");
    CHECK(clipped_text("0123456789", 4) == "0123 [... 6 more bytes]");
    // "é" is two bytes: a cut after 3 bytes of "aéé" would split the second one.
    CHECK(clipped_text("a\xC3\xA9\xC3\xA9", 4) == "a\xC3\xA9 [... 2 more bytes]");
    CHECK(clipped_text("\x01\x02\x03", 100) == times(3, kFffd));
}

TEST_CASE("score_text, metric_text, stage_label: numbers as every report prints them", "[report]") {
    CHECK(score_text(2.5) == "2.5");
    CHECK(score_text(10) == "10");
    CHECK(score_text(1.0 / 3.0) == "0.33");
    CHECK(score_text(0.999) == "1");
    CHECK(score_text(-0.001) == "0");
    CHECK(score_out_of(1.5, 5) == "1.5 / 5");
    // A check short of full points has failed (scored_check): its score must not read as full
    CHECK(score_out_of(0.998, 1) == "0.99 / 1");
    CHECK(score_out_of(20.998, 21) == "20.99 / 21");
    CHECK(score_out_of(1, 1) == "1 / 1");
    CHECK(score_out_of(0.994, 2) == "0.99 / 2");
    // The HTML page's large total, alone
    CHECK(score_below_max_text(20.998, 21) == "20.99");
    CHECK(score_below_max_text(21, 21) == "21");
    CHECK(metric_text(34.1234) == "34.12");
    CHECK(metric_text(0.001234) == "0.001234");
    CHECK(metric_text(1.5e6) == "1.5e+06");
    CHECK(metric_text(INFINITY) == "inf");
    CHECK(stage_label(3) == "stage 3");
    CHECK(stage_label(0) == "pipeline");
}
