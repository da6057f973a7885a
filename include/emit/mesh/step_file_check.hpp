#pragma once
/// \file step_file_check.hpp
/// A STEP file checked before Gmsh's OpenCASCADE kernel reads it (mesh/generate_mesh.hpp, a CAD
/// sheet): the kernel prints its complaints about a malformed file to the terminal and goes on,
/// and on one word where a number should be (a coordinate "NAN") it ran for minutes. emit reads
/// the file's words itself first, one at a time, and refuses in one line what is not STEP.
#include <string>

namespace emit {

/// Reads the STEP file at `path` (ISO 10303-21: it begins "ISO-10303-21;") word by word: strings,
/// comments, entity names (#12), keywords followed by "(" (or the section words HEADER, DATA,
/// ENDSEC, END-ISO-10303-21 followed by ";"), enumerations (.T.), numbers, and = ( ) , ; $ *.
/// Every number must be finite (1E999 is not). Memory does not grow with the file.
/// \throw IoError for a file that is missing or cannot be read; InvalidInput naming the file, the
/// line and the word that is not STEP.
void check_step_file(const std::string& path);

}  // namespace emit
