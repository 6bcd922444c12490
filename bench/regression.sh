#!/usr/bin/env bash
# Runs a fixed, seeded sample of every suite with one binary, for before/after comparisons of a
# change that must not move behaviour (compare two outputs with bench/compare_evals.py).
#   bench/regression.sh BINARY OUT_DIR [EPISODES]
# Each suite's episodes are deterministic for a seed, so two binaries with the same behaviour
# write the same episodes.jsonl apart from timing fields.
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:?usage: bench/regression.sh BINARY OUT_DIR [EPISODES]}"
out="${2:?usage: bench/regression.sh BINARY OUT_DIR [EPISODES]}"
n="${3:-10}"
policy=assets/policies/walk.pt
mkdir -p "$out"
for suite in sit lie reach sceneplan-simple sit-far lie-far reach-far walk walk-step language; do
  extra=()
  case "$suite" in
    *-far|walk|walk-step) extra=(--policy "$policy") ;;
  esac
  args=(--episodes "$n")
  [ "$suite" = language ] && args=()
  "$bin" eval --suite "$suite" "${args[@]}" --seed 1 "${extra[@]}" --out "$out/$suite" \
    > "$out/$suite.log" 2>&1 || echo "$suite: exit $?" >> "$out/errors.txt"
done
echo done > "$out/DONE"
