#pragma once

#include <string>
#include <string_view>

namespace raystep::grade {

/// The text as XML or HTML character data: displayable_text (report_text.h), then `&`, `<`, `>`,
/// `"` and `'` as references, so that nothing a submission wrote (`</pre><script>`, `]]>`, a
/// quote that ends an attribute) can end the element or attribute it sits in. The result reads
/// the same in XML 1.0 and HTML: it uses only references both define (`&amp;`, `&lt;`, `&gt;`,
/// `&quot;` and numeric ones).
std::string markup_text(std::string_view text);

/// markup_text for an attribute value, with tab and newline as character references too: an XML
/// parser turns raw ones into spaces (XML 1.0, section 3.3.3).
std::string markup_attribute(std::string_view text);

}  // namespace raystep::grade
