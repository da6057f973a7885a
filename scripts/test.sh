#!/usr/bin/env bash
# Installs what emit needs, builds the test configuration (AddressSanitizer + UndefinedBehavior-
# Sanitizer, optimised so the FEM tests stay quick) in build-test/, and runs the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEMIT_SANITIZE=ON -DEMIT_BUILD_TESTS=ON >/dev/null
cmake --build build-test -j"$(nproc)"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
cd build-test
ctest --output-on-failure -j"$(nproc)"
