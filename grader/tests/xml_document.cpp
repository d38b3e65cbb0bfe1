#include "xml_document.h"

#include <libxml/parser.h>
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

}  // namespace raystep::testing
