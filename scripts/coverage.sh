#!/usr/bin/env bash
# Measures the test suite's line coverage of the library (src/ only): installs what emit needs
# (gcovr included), builds with gcc's --coverage (-Og, no sanitizers) in build-coverage/, runs the
# suite there, and prints a table per file (the lowest last) and the total; the HTML report goes to
# build-coverage/coverage/index.html. Left out of the run: the fuzz tests (label fuzz: a separate
# clang++ build, which writes no gcc coverage), the browser test (the viewer's JavaScript; the
# server it drives is covered by tests/live/live_server_test.cpp) and the Debian package's test
# (label package: it builds and installs a Release package of its own, which writes no coverage
# here).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
rm -rf build-coverage/coverage
find build-coverage -name '*.gcda' -delete 2>/dev/null || true  # counts from an earlier run
cmake -S . -B build-coverage -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEMIT_COVERAGE=ON -DEMIT_BUILD_TESTS=ON \
      -DEMIT_BUILD_BENCH=OFF >/dev/null
cmake --build build-coverage -j"$(nproc)"
(cd build-coverage && ctest --output-on-failure -j"$(nproc)" -LE 'fuzz|package' -E '^browser_')
mkdir -p build-coverage/coverage
# --filter keeps src/ (the generated viewer page lives in build-coverage/, tests/ is not src/).
# Threads (the live loop, the sources, --threads) race on gcc's plain counters, and now and then
# gcov prints a line gcovr 5.2 cannot read ("branch 1 taken -2"; 2026-11-26 in contacts.cpp):
# gcovr skips that line and says so on stderr. (-fprofile-update=atomic avoids the race, but the
# suite ran 3.5 times slower.)
gcovr --root . --object-directory build-coverage --filter "$PWD/src/" -j "$(nproc)" --sort-percentage \
      --gcov-ignore-parse-errors \
      --print-summary --html-details build-coverage/coverage/index.html --txt -
