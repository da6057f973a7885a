#!/usr/bin/env bash
# Checks that a change leaves emit's output as it was: builds BASE (a git revision) and this tree,
# then compares, byte for byte, the contacts both write for the same inputs:
#   - a recording of 10,000 frames from the twin (made here, or RECORDING), replayed by
#     `emit live --source file:… --fps 0` with the paper method and with contact fitting;
#   - CSV frames through `emit reconstruct`, every method, uncalibrated and calibrated (the
#     calibration files `emit calibrate` writes are compared too).
# A refactoring must pass it. Usage: scripts/same-contacts.sh BASE [RECORDING]
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 1 ] || { echo "usage: scripts/same-contacts.sh BASE [RECORDING]" >&2; exit 2; }
base=$(git rev-parse --verify "$1^{commit}")
recording=${2:-}
work=${TMPDIR:-/tmp}/emit-same-contacts-${base:0:12}
mkdir -p "$work"

# The base, built once in a worktree of its own and kept for later runs.
if [ ! -x "$work/build/emit" ]; then
  rm -rf "$work/src"
  git worktree add --detach "$work/src" "$base" >/dev/null
  cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DEMIT_BUILD_TESTS=OFF -DEMIT_BUILD_BENCH=OFF >/dev/null
  cmake --build "$work/build" -j"$(nproc)" --target emit >/dev/null
  git worktree remove --force "$work/src"
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEMIT_BUILD_TESTS=OFF >/dev/null
cmake --build build -j"$(nproc)" --target emit >/dev/null
old=$work/build/emit
new=$PWD/build/emit
export EMIT_CACHE_DIR=$work/cache

data=$work/data
mkdir -p "$data"
if [ -z "$recording" ]; then
  recording=$data/sim10k.emitrec
  [ -f "$recording" ] || "$new" live --source sim:random --fps 0 --frames 10000 --method paper --record "$recording" \
    >/dev/null 2>&1
fi
if [ ! -f "$data/frames.csv" ]; then
  "$new" simulate --script none --frames 10 --seed 7 --out "$data/reference.csv" >/dev/null 2>&1
  "$new" simulate --script random --frames 40 --force-N 2,39 --seed 8 --out "$data/calibration.csv" >/dev/null 2>&1
  "$new" simulate --script random --frames 200 --force-N 2,39 --seed 9 --out "$data/frames.csv" >/dev/null 2>&1
  "$new" simulate --script two-finger --frames 40 --force-N 5,20 --seed 10 --out "$data/two.csv" >/dev/null 2>&1
fi

differ=0 same=0
compare() {  # compare NAME: $work/old/NAME against $work/new/NAME
  if cmp -s "$work/old/$1" "$work/new/$1"; then
    same=$((same + 1))
    echo "same     $1 ($(wc -c < "$work/new/$1") bytes)"
  else
    differ=$((differ + 1))
    echo "DIFFERS  $1: $(cmp "$work/old/$1" "$work/new/$1" 2>&1 | head -1)"
  fi
}
for side in old new; do
  rm -rf "${work:?}/$side"
  mkdir -p "$work/$side"
done
run() {  # run NAME ARGS...: both binaries, output to $work/{old,new}/NAME
  local name=$1
  shift
  for side in old new; do
    local emit=${!side}
    (cd "$work/$side" && "$emit" "${@//@OUT@/$work/$side/$name}" >/dev/null 2>"$work/$side/$name.log") ||
      { echo "FAILED   $side: emit $*" >&2; cat "$work/$side/$name.log" >&2; exit 1; }
  done
  compare "$name"
}
for method in paper fit; do
  run "replay_$method.jsonl" live --source "file:$recording" --fps 0 --method "$method" --contacts @OUT@
done
for method in paper noser laplacian fit; do
  for frames in frames two; do
    run "${frames}_$method.jsonl" reconstruct --method "$method" --reference "$data/reference.csv" \
      --frames "$data/$frames.csv" --contacts @OUT@
  done
  run "calibration_$method.json" calibrate --method "$method" --reference "$data/reference.csv" \
    --frames "$data/calibration.csv" --truth "$data/calibration_presses.csv" --out @OUT@
  for side in old new; do cp "$work/$side/calibration_$method.json" "$work/$side/c.json"; done
  run "calibrated_$method.jsonl" reconstruct --method "$method" --reference "$data/reference.csv" \
    --frames "$data/frames.csv" --calibration c.json --contacts @OUT@
done
echo "$same the same, $differ different (base ${base:0:12}, recording $recording)"
[ "$differ" -eq 0 ]
