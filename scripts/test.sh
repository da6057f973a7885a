#!/usr/bin/env bash
# Installs what emit needs, builds the test configuration (AddressSanitizer + UndefinedBehavior-
# Sanitizer, optimised so the FEM tests stay quick) in build-test/, and runs the whole suite.
# Line tables only (-g1: the sanitizers' reports still name file and line) and no benchmarks
# (lint.sh still checks they compile): the build takes about a third less time. Compiles go
# through ccache when it is installed (CMakeLists.txt), so a second clone rebuilds in minutes.
# Ends with each stage's time and the 20 slowest tests.
#
# Usage: scripts/test.sh [CTEST ARGUMENTS...], e.g. scripts/test.sh -L quick (the inner loop)
set -euo pipefail
cd "$(dirname "$0")/.."
stages=()
started=$(date +%s)
stage_start=$started
stage_done() {  # stage_done NAME: the time since the last stage ended
  local now
  now=$(date +%s)
  stages+=("$1 $((now - stage_start)) s")
  stage_start=$now
}
report() {
  (IFS=,; echo "test.sh: ${stages[*]/#/ }; total $(($(date +%s) - started)) s")
}
trap report EXIT

scripts/install-deps.sh
stage_done dependencies
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DEMIT_SANITIZE=ON -DEMIT_BUILD_TESTS=ON -DEMIT_BUILD_BENCH=OFF >/dev/null
cmake --build build-test -j"$(nproc)"
stage_done build
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
cd build-test
set +e
ctest --output-on-failure -j"$(nproc)" "$@" | tee ctest.log
status=${PIPESTATUS[0]}
set -e
stage_done tests
echo "test.sh: the 20 slowest tests (seconds):"
sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: ([^ ]+) [. ]*[A-Za-z*]+.* ([0-9.]+) sec$/\2 \1/p' ctest.log | sort -rn |
  awk 'NR <= 20 {printf "  %7.1f  %s\n", $1, $2}'  # awk reads to the end: no SIGPIPE for sort
exit $status
