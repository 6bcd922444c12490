#!/usr/bin/env bash
# Runs the benchmark suites whose numbers are in docs/BENCHMARKS.md. Long: run it in the
# background (nohup bench/run_benchmarks.sh &). Each eval keeps what finished if interrupted.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out/bench}"
mkdir -p "$out/fast" "$out/quality"
bin=build/simhuman
"$bin" --version > "$out/version.txt"
build/simhuman_step_bench living_room 20000 > "$out/step_bench.json"
for preset in fast quality; do
  n=50
  [ "$preset" = quality ] && n=20
  for suite in sit lie reach sceneplan-simple; do
    "$bin" eval --suite "$suite" --episodes "$n" --seed 1 --preset "$preset" \
      --out "$out/$preset/$suite" > "$out/$preset/$suite.log" 2>&1 || true
  done
done
echo done > "$out/DONE"
