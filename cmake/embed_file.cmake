# Turns a file into a C++ source defining `std::string_view <NAME>()` with its bytes, so the
# binary carries it (the live viewer's page and three.js work from any directory). Without INPUT
# (empty), the function returns an empty view: a file left out of the build.
# Usage: cmake -DINPUT=file -DOUTPUT=file.cpp -DNAME=function -DHEADER=include/path.hpp -P embed_file.cmake
#
# The bytes are one string literal of \xNN escapes, 32 to a line (adjacent literals concatenate):
# compilers read a long literal far faster than a brace list of as many chars (three.js's 1.5 MB
# compile in about a second instead of a dozen), and every byte escaped keeps any content exact.
if(INPUT)
  file(READ "${INPUT}" hex HEX)
  set(from "${INPUT}")
else()
  set(hex "")
  set(from "nothing (left out of this build)")
endif()
string(LENGTH "${hex}" hex_length)
math(EXPR byte_count "${hex_length} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "\\\\x\\1" bytes "${hex}")
string(REGEX REPLACE "((\\\\x[0-9a-f][0-9a-f]){32})" "\\1\"\n\"" bytes "${bytes}")
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${from} by cmake/embed_file.cmake; do not edit.\n"
  "#include \"${HEADER}\"\n\n"
  "// One literal longer than the 65,536 characters the standard asks compilers to support: GCC and\n"
  "// Clang take it (clang warns under -Wpedantic).\n"
  "#pragma GCC diagnostic ignored \"-Woverlength-strings\"\n\n"
  "namespace emit {\n\nnamespace {\nconstexpr char bytes[] =\n\"${bytes}\";\n}  // namespace\n\n"
  "std::string_view ${NAME}() { return {bytes, ${byte_count}}; }\n\n}  // namespace emit\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
