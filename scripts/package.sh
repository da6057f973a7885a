#!/usr/bin/env bash
# Builds emit's Debian package and checks it with lintian: a Release build for /usr in build-deb/
# (or the folder given), `cpack -G DEB` (cmake/debian_package.cmake), then lintian, which must
# report no error. Prints the package's path and lintian's count of warnings on the last line.
#
# Usage: scripts/package.sh [BUILD_DIR]
# Then:  sudo apt install ./build-deb/emit_<version>_<arch>.deb
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-deb}
scripts/install-deps.sh
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr -DEMIT_BUILD_TESTS=OFF \
  -DEMIT_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j"$(nproc)"
rm -f "$build"/emit_*.deb
(cd "$build" && cpack -G DEB >cpack.log 2>&1) || { cat "$build/cpack.log" >&2; exit 1; }
deb=$(ls "$build"/emit_*.deb)

# lintian's findings, each on its line ("E: emit: <tag> <where>"); errors fail, warnings are listed,
# and so are the findings the package overrides (O:, cmake/debian/lintian-overrides says why).
# lintian warns that it runs as root, which is not a finding about the package: left out.
findings=$(lintian --tag-display-limit 0 --show-overrides "$deb" 2>&1 | grep -v "running with root privileges" || true)
[ -z "$findings" ] || printf '%s\n' "$findings"
errors=$(printf '%s\n' "$findings" | grep -c '^E: ' || true)
warnings=$(printf '%s\n' "$findings" | grep -c '^W: ' || true)
if [ "$errors" -gt 0 ]; then
  echo "package: $deb: lintian found $errors errors ($warnings warnings)" >&2
  exit 1
fi
overridden=$(printf '%s\n' "$findings" | grep -c '^O: ' || true)
echo "package: $deb ($(du -k "$deb" | cut -f1) KiB): lintian: 0 errors, $warnings warnings, $overridden overridden"
