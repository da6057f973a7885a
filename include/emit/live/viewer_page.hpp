#pragma once
/// \file viewer_page.hpp
/// The live viewer's page (viewer/index.html: HTML, CSS and JavaScript in one file, nothing fetched
/// from elsewhere), and three.js for its 3D view of curved sheets, embedded into the library at
/// build time (CMakeLists.txt) and served by the live server (live_server.hpp).
#include <string_view>

namespace emit {

std::string_view viewer_page();

/// three.js (npm's `three`, pinned in viewer/package.json and viewer/package-lock.json, installed in
/// viewer/node_modules by scripts/install-deps.sh): its ES modules build/three.module.js (which
/// imports ./three.core.js) and build/three.core.js, and the addon
/// examples/jsm/controls/OrbitControls.js (which imports 'three': the page's import map says where).
/// Each is empty when the build left three.js out (it was not installed when CMake configured the
/// build, and CMake said so); the page then draws curved sheets flat and says why.
std::string_view three_module_js();
std::string_view three_core_js();
std::string_view three_orbit_controls_js();

}  // namespace emit
