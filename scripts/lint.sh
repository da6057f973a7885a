#!/usr/bin/env bash
# Lints emit: the formatting (.clang-format, clang-format --dry-run -Werror on the tracked C++ files
# of include/ src/ cli/ bench/ tests/) and clang-tidy (.clang-tidy) on every translation unit of
# src/, cli/, bench/, tests/ (and the generated sources), in parallel. Exits non-zero on any
# formatting difference or clang-tidy warning, and ends with a one-line summary.
#
# Usage: scripts/lint.sh [format|tidy] [--full]   (default: both)
# clang-tidy's result for a unit is reused while nothing it reads changed (its preprocessed text,
# flags, the .clang-tidy files, clang-tidy's version: scripts/clang_tidy_cached.py), from a cache
# outside the clone ($EMIT_LINT_CACHE, default ~/.cache/emit/clang-tidy) that every clone on the
# machine shares; --full runs clang-tidy on every unit afresh.
# Environment: EMIT_LINT_BUILD_DIR (default build-lint), EMIT_LINT_JOBS (default: nproc), EMIT_LINT_CACHE.
# The build directory is configured (no sanitizer, tests and benchmarks on, so their files are in
# compile_commands.json) but not built: only the generated sources are made. clang-tidy's full
# output per translation unit is kept in $EMIT_LINT_BUILD_DIR/lint/.
set -euo pipefail
cd "$(dirname "$0")/.."
what=all
full=0
for argument in "$@"; do
  case "$argument" in
    all | format | tidy) what=$argument ;;
    --full) full=1 ;;
    *) echo "usage: scripts/lint.sh [format|tidy] [--full]" >&2; exit 2 ;;
  esac
done
build=${EMIT_LINT_BUILD_DIR:-build-lint}
jobs=${EMIT_LINT_JOBS:-$(nproc)}
start=$(date +%s)

scripts/install-deps.sh
clang_format=$(command -v clang-format-14 || command -v clang-format)
clang_tidy=$(command -v clang-tidy-14 || command -v clang-tidy)

summary=()
failed=0

# Formatting: every tracked C++ file of the library, the CLI, the benchmarks and the tests
# (firmware/ keeps its own style: it is also compiled freestanding for the board).
if [ "$what" != tidy ]; then
  mapfile -t format_files < <(git ls-files -- 'include/*.hpp' 'include/*.cpp' 'src/*.hpp' 'src/*.cpp' 'cli/*.hpp' \
    'cli/*.cpp' 'bench/*.hpp' 'bench/*.cpp' 'tests/*.hpp' 'tests/*.cpp' 'python/*.hpp' 'python/*.cpp')
  unformatted=()
  for file in "${format_files[@]}"; do
    "$clang_format" --dry-run -Werror "$file" >/dev/null 2>&1 || unformatted+=("$file")
  done
  if [ ${#unformatted[@]} -eq 0 ]; then
    summary+=("${#format_files[@]} files formatted")
  else
    failed=1
    lines=0
    for file in "${unformatted[@]}"; do
      changed=$("$clang_format" "$file" | diff "$file" - | grep -c '^<' || true)
      echo "format: $file: $changed lines differ (clang-format -i $file)"
      lines=$((lines + changed))
    done
    summary+=("${#unformatted[@]} of ${#format_files[@]} files not formatted ($lines lines)")
  fi
fi

# clang-tidy: every translation unit in the compilation database under src/, cli/, bench/, tests/,
# python/ and the build's generated sources. The fuzz targets (tests/fuzz/, compiled by clang++ outside
# CMake's targets, so not in the database) are left to their own -Wall -Wextra -Werror build.
if [ "$what" != format ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DEMIT_SANITIZE=OFF -DEMIT_BUILD_TESTS=ON -DEMIT_BUILD_BENCH=ON \
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
  cmake --build "$build" --target emit_generated_sources >/dev/null
  root=$PWD
  logs=$build/lint
  rm -rf "$logs"
  mkdir -p "$logs"
  mapfile -t units < <(
    python3 - "$build/compile_commands.json" "$root" "$root/$build" <<'EOF'
import json, os, sys
database, root, build = sys.argv[1:]
for entry in json.load(open(database)):
    path = os.path.normpath(os.path.join(entry["directory"], entry["file"]))
    if path.startswith(build + "/generated/") or any(path.startswith(f"{root}/{d}/") for d in ("src", "cli", "bench", "tests", "python")):
        print(path)
EOF
  )
  # One clang-tidy per unit, $jobs at a time, each writing its own log (no interleaving); a unit
  # whose preprocessed text, flags and configuration are those of an earlier run reuses that run's
  # result (scripts/clang_tidy_cached.py says how; --full runs every unit).
  clang=$(command -v clang++-14 || command -v clang++)
  cache_flag=()
  [ "$full" -eq 1 ] && cache_flag=(--no-cache)
  tidy_summary=$(python3 scripts/clang_tidy_cached.py --clang-tidy "$clang_tidy" --clang "$clang" --build "$build" \
    --root "$root" --logs "$logs" --jobs "$jobs" "${cache_flag[@]}" $(printf '%s\n' "${units[@]}" | sort -u))
  # A header's warning shows once per unit that includes it: count each once.
  diagnostics=$(cat "$logs"/*.log | grep -E '^[^ ]+:[0-9]+:[0-9]+: (warning|error):|^clang-tidy exited' | sort -u || true)
  count=$(printf '%s' "$diagnostics" | grep -c . || true)
  if [ "$count" -eq 0 ]; then
    summary+=("clang-tidy: 0 warnings in $tidy_summary")
  else
    failed=1
    printf '%s\n' "$diagnostics" | sed "s|^$root/||"
    by_check=$(printf '%s\n' "$diagnostics" | grep -oE '\[[a-z0-9.,-]+\]$' | sort | uniq -c | sort -rn |
      awk '{printf "%s%s %s", (NR > 1 ? ", " : ""), $1, $2}')
    summary+=("clang-tidy: $count warnings in $tidy_summary ($by_check; full output in $logs/)")
  fi
fi

elapsed=$(($(date +%s) - start))
verdict=$([ $failed -eq 0 ] && echo clean || echo FAILED)
(IFS=';'; echo "lint: $verdict: ${summary[*]/#/ } (${elapsed} s)")
exit $failed
