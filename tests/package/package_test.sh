#!/usr/bin/env bash
# The Debian package as a user meets it (CTest's debian_package):
#   1. scripts/package.sh builds it (a Release build for /usr, cpack -G DEB) and lintian finds no error;
#   2. apt installs it, and it holds what it promises (the command, the library, the headers, the
#      CMake config, the Python module, the example sensors);
#   3. tests/package/downstream, a user's CMake project, builds against the installed package
#      (find_package(emit COMPONENTS core), emit::emit and emit::core), reconstructs a press of the
#      twin within 0.5 mm, and, linking the core alone (no Boost, DDS, OpenCASCADE, libpng: ldd),
#      frames the installed command wrote;
#   4. the README's Python section runs as written with the installed module and command;
#   5. the package is removed again (also when a step fails).
# Installing needs root (or sudo without a password); without it the test is skipped (exit 77). So
# it is when a package named emit is installed already: the test installs and removes its own, and
# leaves a user's alone.
#
# Usage: tests/package/package_test.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$(cd "$1" && pwd)
work=$2
mkdir -p "$work"
work=$(cd "$work" && pwd)

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo -n true 2>/dev/null || { echo "skipped: installing the package needs root or sudo without a password"; exit 77; }
  sudo="sudo -n"
fi
if dpkg-query -W -f='${Status}' emit 2>/dev/null | grep -q "install ok installed"; then
  echo "skipped: a package emit is installed on this machine already; this test would replace and remove it"
  exit 77
fi

echo "== 1. build the package, lint it"
"$source_dir/scripts/package.sh" "$work/build" | tail -n 1
deb=$(ls "$work"/build/emit_*.deb)

echo "== 2. install it"
installed=0
cleanup() {
  if [ $installed -eq 1 ]; then
    echo "== 5. remove it"
    $sudo dpkg --purge emit >/dev/null
  fi
}
trap cleanup EXIT
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "$deb" >"$work/apt.log" 2>&1 ||
  { cat "$work/apt.log"; exit 1; }
installed=1
triplet=$(gcc -print-multiarch)
python_dir=/usr/lib/python3/dist-packages/emit
for path in /usr/bin/emit "/usr/lib/$triplet/libemit_core.so" "/usr/lib/$triplet/emit/libemit_gmsh.so" \
  "/usr/lib/$triplet/libemit_jobs.so" "/usr/lib/$triplet/cmake/emit/emitConfig.cmake" \
  /usr/include/emit/pipeline/pipeline.hpp /usr/include/emit/firmware/core/frame_packet.hpp \
  "$python_dir/__init__.py" "$python_dir/_emit.pyi" /usr/share/emit/sensors/dome25.json \
  /usr/share/doc/emit/copyright; do
  [ -e "$path" ] || { echo "the package does not install $path"; exit 1; }
done
# The installed command and module find the installed library, not a build tree's.
loads_installed_library() {
  local loaded
  loaded=$(ldd "$1" | awk '$1 ~ /^libemit_core\.so/ {print $3}')
  [ -n "$loaded" ] && [ "$(readlink -f "$loaded")" = "$(readlink -f "/usr/lib/$triplet/libemit_core.so")" ] ||
    { echo "$1 does not load /usr/lib/$triplet/libemit_core.so:"; ldd "$1"; return 1; }
}
loads_installed_library /usr/bin/emit
loads_installed_library "$(ls "$python_dir"/_emit.cpython-*.so)"
/usr/bin/emit --help >/dev/null

echo "== 3. a downstream CMake project against it"
rm -rf "$work/downstream"
cmake -S "$source_dir/tests/package/downstream" -B "$work/downstream" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/downstream" -j"$(nproc)" >/dev/null
grep -q "/usr/lib/$triplet/cmake/emit" "$work/downstream/CMakeCache.txt" ||
  { echo "the downstream project did not find the installed package's config"; exit 1; }
loads_installed_library "$work/downstream/reconstruct_press"
"$work/downstream/reconstruct_press" 20 40
# The core alone: frames the installed command wrote, reconstructed by a program that links
# emit::core, which brings no Boost, DDS, OpenCASCADE (Gmsh's) or libpng.
/usr/bin/emit simulate --script none --frames 10 --out "$work/untouched.csv" >/dev/null 2>&1
/usr/bin/emit simulate --press 20,40,5,10 --out "$work/pressed.csv" >/dev/null 2>&1
core_links=$(ldd "$work/downstream/reconstruct_frames")
[ -n "$(printf '%s\n' "$core_links" | awk '$1 ~ /^libemit_core\.so/')" ] ||
  { echo "reconstruct_frames does not link libemit_core:"; printf '%s\n' "$core_links"; exit 1; }
heavy=$(printf '%s\n' "$core_links" | grep -E 'libboost|libddsc|libcyclone|libTK|libpng|libgmsh|libemit_(io|live|eval|jobs)' || true)
[ -z "$heavy" ] || { echo "a program of emit::core links more than the core:"; printf '%s\n' "$heavy"; exit 1; }
echo "reconstruct_frames links $(printf '%s\n' "$core_links" | wc -l) libraries, none of Boost, DDS, OpenCASCADE, libpng, Gmsh"
"$work/downstream/reconstruct_frames" "$work/untouched.csv" "$work/pressed.csv" 20 40

echo "== 4. the README's Python section, with the installed module and command"
env -u PYTHONPATH -u LD_PRELOAD EMIT_INSTALLED=1 EMIT_CLI=/usr/bin/emit EMIT_SOURCE_DIR="$source_dir" \
  /usr/bin/python3 -m pytest -q -p no:cacheprovider "$source_dir/tests/python/test_docs.py" \
  -k test_the_readme_python_section_as_written
echo "package test: passed"
