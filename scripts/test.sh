#!/usr/bin/env bash
# Installs what emit needs, builds the test configuration (AddressSanitizer + UndefinedBehavior-
# Sanitizer, optimised so the FEM tests stay quick) in build-test/, and runs the whole suite.
# Line tables only (-g1: the sanitizers' reports still name file and line) and no benchmarks
# (lint.sh still checks they compile): the build takes about a third less time.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DEMIT_SANITIZE=ON -DEMIT_BUILD_TESTS=ON -DEMIT_BUILD_BENCH=OFF >/dev/null
cmake --build build-test -j"$(nproc)"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
cd build-test
ctest --output-on-failure -j"$(nproc)"
