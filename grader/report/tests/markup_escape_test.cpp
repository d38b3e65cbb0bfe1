#include "grader/report/markup_escape.h"

#include "app/report/report_text.h"
#include "base/testing/catch.h"
#include "report_example.h"
#include "xml_document.h"

using namespace raystep::grade;
using raystep::testing::kHostile;
using raystep::testing::XmlDocument;

TEST_CASE("markup_text: the five special characters as references", "[report]") {
    CHECK(markup_text("a < b && c > \"d\" 'e'") ==
          "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &#39;e&#39;");
    CHECK(markup_text("</pre><script>") == "&lt;/pre&gt;&lt;script&gt;");
    CHECK(markup_text("line\n\tnext") == "line\n\tnext");
    CHECK(markup_attribute("line\n\tnext") == "line&#10;&#9;next");
}

TEST_CASE("markup_text: hostile text reads back from a real XML parser as its displayable self",
          "[report]") {
    for (const std::string& text :
         {kHostile, std::string("]]>"), std::string("&lt; is not <"), std::string("\x00\x01", 2),
          std::string("multi\nline\tattribute")}) {
        CAPTURE(text);
        const XmlDocument document("<a b=\"" + markup_attribute(text) + "\" c='" +
                                   markup_attribute(text) + "'>" + markup_text(text) + "</a>");
        REQUIRE(document.well_formed());
        CHECK(document.values("/a/@b") == std::vector<std::string>{displayable_text(text)});
        CHECK(document.values("/a/@c") == std::vector<std::string>{displayable_text(text)});
        CHECK(document.values("/a") == std::vector<std::string>{displayable_text(text)});
    }
}
