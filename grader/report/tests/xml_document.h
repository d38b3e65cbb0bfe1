#pragma once

#include <libxml/tree.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

// A document parsed by libxml2 as strict XML 1.0, for the tests of the reports that must be
// well-formed (JUnit XML, and the HTML report, which is written to be well-formed XML too): a real
// parser, so that the tests do not trust an escaping function to check itself.

namespace raystep::testing {

class XmlDocument {
  public:
    /// Parses the text with no network and no entity expansion beyond XML's five; `errors()`
    /// holds the parser's messages, and every query on a document that did not parse is empty.
    explicit XmlDocument(const std::string& text);

    bool well_formed() const { return document_ != nullptr; }
    const std::string& errors() const { return errors_; }

    /// The string values of the nodes an XPath 1.0 expression selects, in document order
    /// (an attribute's value, an element's text); empty when it selects none.
    std::vector<std::string> values(const std::string& xpath) const;

    /// How many nodes the expression selects.
    std::size_t count(const std::string& xpath) const { return values(xpath).size(); }

    /// What makes the document invalid against the XML Schema (XSD 1.0) in the file, in
    /// libxml2's words; empty when it is valid. A document that did not parse, or a schema that
    /// cannot be read, is reported too, so that empty always means valid.
    std::string schema_violations(const std::filesystem::path& schema) const;

  private:
    struct FreeDocument {
        void operator()(xmlDoc* document) const { xmlFreeDoc(document); }
    };
    std::unique_ptr<xmlDoc, FreeDocument> document_;
    std::string errors_;
};

}  // namespace raystep::testing
