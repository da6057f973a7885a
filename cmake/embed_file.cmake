# Turns a file into a C++ source defining `std::string_view <NAME>()` with its bytes, so the
# binary carries it (the live viewer's page works from any directory).
# Usage: cmake -DINPUT=file -DOUTPUT=file.cpp -DNAME=function -DHEADER=include/path.hpp -P embed_file.cmake
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" hex_length)
math(EXPR byte_count "${hex_length} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
string(REGEX REPLACE "(('\\\\x[0-9a-f][0-9a-f]',){16})" "\\1\n" bytes "${bytes}")
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${INPUT} by cmake/embed_file.cmake; do not edit.\n"
  "#include \"${HEADER}\"\n\n"
  "namespace emit {\n\nnamespace {\nconstexpr char bytes[] = {\n${bytes}'\\0'};\n}  // namespace\n\n"
  "std::string_view ${NAME}() { return {bytes, ${byte_count}}; }\n\n}  // namespace emit\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
