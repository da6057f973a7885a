#pragma once
/// \file version.hpp
/// emit's version, as the library was built (the project's in CMakeLists.txt): the CLI's
/// --version, Python's emit.__version__ and the writer MCAP files name all read it here. A
/// program built against an installed libemit.so can compare it with the headers' own package
/// version (find_package(emit) checks that).

namespace emit {

/// "MAJOR.MINOR.PATCH", e.g. "0.1.0".
const char* version();

}  // namespace emit
