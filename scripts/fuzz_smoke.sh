#!/usr/bin/env bash
# Fuzz smoke test: builds the libFuzzer targets of tests/fuzz/*_fuzz.cc with clang
# (address + undefined sanitizers) in build-fuzz/ and runs each for a bounded time from its seed
# corpus (tests/fuzz/corpus/<target>/, read only; new inputs go to a temporary folder).
# Fails on any crash, sanitizer report, leak or timeout; the input that did it is kept as
# build-fuzz/artifacts/<target>-crash-*  (replay: build-fuzz/<target> <file>).
#
#   scripts/fuzz_smoke.sh [seconds per target]     default 20 (or $FUZZ_SECONDS)
#   SIMHUMAN_FUZZ_BUILD_DIR=dir  JOBS=n            build folder (build-fuzz), build jobs (2)
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${1:-${FUZZ_SECONDS:-20}}"
build="${SIMHUMAN_FUZZ_BUILD_DIR:-build-fuzz}"
jobs="${JOBS:-2}"

if ! command -v clang >/dev/null 2>&1 || ! command -v clang++ >/dev/null 2>&1; then
  echo "clang not found: fuzz smoke skipped"
  exit 0
fi

start=$(date +%s)
mkdir -p "$build"
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSIMHUMAN_FUZZ=ON \
  >"$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j "$jobs" --target fuzz_targets
built=$(date +%s)
echo "fuzz smoke: build took $((built - start)) s"

mkdir -p "$build/artifacts" "$build/logs"
status=0
for src in tests/fuzz/*_fuzz.cc; do
  target="$(basename "$src" .cc)"
  work="$(mktemp -d)"
  seeds=()
  [[ -d "tests/fuzz/corpus/$target" ]] && seeds=("tests/fuzz/corpus/$target")
  log="$build/logs/$target.log"
  t0=$(date +%s)
  if "$build/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="$build/artifacts/$target-" "$work" "${seeds[@]}" >"$log" 2>&1; then
    runs=$(grep -o 'Done [0-9]* runs' "$log" | tail -1 || true)
    echo "fuzz smoke: $target ok (${runs:-done}, $(( $(date +%s) - t0 )) s)"
  else
    echo "fuzz smoke: $target FAILED; log $log; last lines:"
    tail -n 40 "$log"
    status=1
  fi
  rm -rf "$work"
done
echo "fuzz smoke: total $(( $(date +%s) - start )) s"
exit "$status"
