#pragma once
/// \file viewer_page.hpp
/// The live viewer's page (viewer/index.html: HTML, CSS and JavaScript in one file, no external
/// resources), embedded into the library at build time.
#include <string_view>

namespace emit {

std::string_view viewer_page();

}  // namespace emit
