#include "xml_document.h"

#include <libxml/parser.h>
#include <libxml/xmlschemas.h>
#include <libxml/xpath.h>

#include <cstdarg>
#include <cstdio>

namespace raystep::testing {

namespace {

// libxml2 reports errors through a printf-like callback; this one appends them to a string.
void collect_error(void* context, const char* format, ...) {
    char buffer[1024];
    va_list arguments;
    va_start(arguments, format);
    std::vsnprintf(buffer, sizeof buffer, format, arguments);
    va_end(arguments);
    *static_cast<std::string*>(context) += buffer;
}

}  // namespace

XmlDocument::XmlDocument(const std::string& text) {
    xmlSetGenericErrorFunc(&errors_, collect_error);
    document_.reset(xmlReadMemory(text.data(), static_cast<int>(text.size()), "report.xml", nullptr,
                                  XML_PARSE_NONET));
    xmlSetGenericErrorFunc(nullptr, nullptr);
}

std::vector<std::string> XmlDocument::values(const std::string& xpath) const {
    std::vector<std::string> found;
    if (!document_) return found;
    xmlXPathContextPtr context = xmlXPathNewContext(document_.get());
    xmlXPathObjectPtr result =
        xmlXPathEvalExpression(reinterpret_cast<const xmlChar*>(xpath.c_str()), context);
    if (result != nullptr && result->nodesetval != nullptr) {
        for (int k = 0; k < result->nodesetval->nodeNr; ++k) {
            xmlChar* value = xmlNodeGetContent(result->nodesetval->nodeTab[k]);
            found.emplace_back(value != nullptr ? reinterpret_cast<const char*>(value) : "");
            xmlFree(value);
        }
    }
    xmlXPathFreeObject(result);
    xmlXPathFreeContext(context);
    return found;
}

std::string XmlDocument::schema_violations(const std::filesystem::path& schema) const {
    if (!document_) return "the document is not well-formed XML: " + errors_;
    std::string violations;
    xmlSchemaParserCtxtPtr parser = xmlSchemaNewParserCtxt(schema.c_str());
    xmlSchemaSetParserErrors(parser, collect_error, collect_error, &violations);
    xmlSchemaPtr parsed = xmlSchemaParse(parser);
    xmlSchemaFreeParserCtxt(parser);
    if (parsed == nullptr)
        return "the schema " + schema.string() + " cannot be read: " + violations;
    xmlSchemaValidCtxtPtr validator = xmlSchemaNewValidCtxt(parsed);
    xmlSchemaSetValidErrors(validator, collect_error, collect_error, &violations);
    const int result = xmlSchemaValidateDoc(validator, document_.get());
    xmlSchemaFreeValidCtxt(validator);
    xmlSchemaFree(parsed);
    if (result != 0 && violations.empty()) violations = "invalid (libxml2 gave no message)";
    return violations;
}

}  // namespace raystep::testing
