#!/usr/bin/env python3
"""Compares two bench/regression.sh outputs episode by episode, ignoring timing fields.

usage: bench/compare_evals.py BEFORE_DIR AFTER_DIR
Prints one line per suite (identical / the first differing episode and key) and exits 1 when
any suite differs or is missing.
"""
import json
import pathlib
import sys

TIMING = {"wall_time_s", "wall_per_sim", "steps_per_s", "elapsed_s"}


def strip(value):
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items() if k not in TIMING}
    if isinstance(value, list):
        return [strip(v) for v in value]
    return value


def first_difference(a, b, path=""):
    if type(a) is not type(b):
        return path or "/"
    if isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                return f"{path}/{k}"
            d = first_difference(a[k], b[k], f"{path}/{k}")
            if d:
                return d
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{path} (length {len(a)} vs {len(b)})"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{path}/{i}")
            if d:
                return d
        return None
    return None if a == b else path or "/"


def main():
    before, after = map(pathlib.Path, sys.argv[1:3])
    bad = 0
    for eps in sorted(before.glob("*/episodes.jsonl")):
        suite = eps.parent.name
        other = after / suite / "episodes.jsonl"
        if not other.exists():
            print(f"{suite}: missing in {after}")
            bad += 1
            continue
        a = [strip(json.loads(l)) for l in eps.read_text().splitlines() if l.strip()]
        b = [strip(json.loads(l)) for l in other.read_text().splitlines() if l.strip()]
        if len(a) != len(b):
            print(f"{suite}: {len(a)} vs {len(b)} episodes")
            bad += 1
            continue
        diff = next(((i, d) for i, (x, y) in enumerate(zip(a, b))
                     if (d := first_difference(x, y))), None)
        if diff:
            print(f"{suite}: episode {diff[0]} differs at {diff[1]}")
            bad += 1
        else:
            print(f"{suite}: {len(a)} episodes identical")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
