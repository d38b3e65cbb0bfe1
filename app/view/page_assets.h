#pragma once

#include <string_view>
#include <vector>

namespace raystep {

/// A file of the page `raystep view` serves, built into the program from app/view/page/ so that
/// the page is always the one the program was built with, and no file is read to serve it.
struct PageAsset {
    std::string_view path;          ///< the URL path: "/", "/view.js", "/view.css"
    std::string_view content_type;  ///< "text/html; charset=utf-8"
    std::string_view text;
};

/// Every file of the page.
const std::vector<PageAsset>& page_assets();

}  // namespace raystep
