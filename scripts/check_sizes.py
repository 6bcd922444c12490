#!/usr/bin/env python3
"""Checks the house size limits: no source file over 800 lines, no function over 150 lines.

usage: scripts/check_sizes.py [ROOT]   (default: src/)
A function starts at a declaration at column 0 whose line, or an indented continuation line,
opens a body with "{", and ends at the next "}" at column 0 (clang-format's layout); lambdas
inside a function count toward it. Test files (*_test.cc) are
left out. Prints each violation and exits 1 when there is any.
"""
import pathlib
import re
import sys

MAX_FILE_LINES = 800
MAX_FUNCTION_LINES = 150
SKIP = ("namespace", "struct", "class", "enum", "union", "using", "typedef", "template", "#",
        "extern", "static_assert", "//")


def functions(lines):
    start = pending = None
    for i, line in enumerate(lines):
        text = line.rstrip()
        if start is not None:
            if line.startswith("}"):
                yield start, i
                start = None
            continue
        if re.match(r"^[A-Za-z_]", line) and not line.startswith(SKIP):
            if text.endswith("{"):
                start, pending = i, None
            elif not text.endswith((";", "}")):
                pending = i
        elif pending is not None:
            if text.endswith("{"):
                start, pending = pending, None
            elif text.endswith(";") or not line.startswith(" "):
                pending = None


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "src")
    bad = 0
    for path in sorted(root.rglob("*")):
        if path.suffix not in (".cc", ".h") or path.name.endswith("_test.cc"):
            continue
        lines = path.read_text().split("\n")
        if len(lines) > MAX_FILE_LINES:
            print(f"{path}: {len(lines)} lines (limit {MAX_FILE_LINES})")
            bad += 1
        if path.suffix != ".cc":
            continue
        for s, e in functions(lines):
            n = e - s + 1
            if n > MAX_FUNCTION_LINES:
                print(f"{path}:{s + 1}: function of {n} lines (limit {MAX_FUNCTION_LINES}): "
                      f"{lines[s].strip()[:80]}")
                bad += 1
    print(f"check_sizes: {bad} violation(s)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
