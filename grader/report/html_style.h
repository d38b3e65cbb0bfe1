#pragma once

#include <string_view>

namespace raystep::grade {

/// The HTML report's style sheet, inlined in its <head> so that the page needs no other file and
/// no network. Plain CSS with neither `<` nor `&`, so the page stays well-formed XML too.
std::string_view html_style();

}  // namespace raystep::grade
