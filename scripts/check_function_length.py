#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Fails when a function in src/ is longer than the project's limit (120 lines; docs/contributing/architecture.md).

Uses Universal Ctags (its `end` field) to find every C++ function definition and its extent.
Usage: check_function_length.py [SRC_DIR] [--limit N] [--top K]
Prints the K longest functions; exit 1 when any exceeds the limit, 2 when ctags is missing."""
import argparse
import json
import shutil
import subprocess
import sys


def functions(src_dir):
    """(lines, path, name) of every function definition ctags finds under src_dir."""
    output = subprocess.run(
        ["ctags", "-R", "--languages=C++", "--fields=+ne", "--output-format=json",
         "--kinds-C++=f", "-f", "-", src_dir],
        check=True, capture_output=True, text=True).stdout
    rows = []
    for line in output.splitlines():
        if not line.startswith("{"):
            continue
        tag = json.loads(line)
        if "end" in tag:
            rows.append((tag["end"] - tag["line"] + 1, tag["path"], tag["name"], tag["line"]))
    return sorted(rows, reverse=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("src", nargs="?", default="src")
    parser.add_argument("--limit", type=int, default=120)
    parser.add_argument("--top", type=int, default=5)
    args = parser.parse_args()
    if not shutil.which("ctags"):
        print("check_function_length: ctags (universal-ctags) not found", file=sys.stderr)
        return 2
    rows = functions(args.src)
    if not rows:
        print(f"check_function_length: no functions found under {args.src}", file=sys.stderr)
        return 2
    print(f"{len(rows)} functions under {args.src}; the longest:")
    for lines, path, name, first in rows[:args.top]:
        print(f"  {lines:4d} lines  {path}:{first}  {name}")
    too_long = [r for r in rows if r[0] > args.limit]
    for lines, path, name, first in too_long:
        print(f"FAIL {path}:{first} {name}: {lines} lines > {args.limit}")
    print(f"{len(rows) - len(too_long)} passed, {len(too_long)} failed")
    return 1 if too_long else 0


if __name__ == "__main__":
    sys.exit(main())
