#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks that the repository explains itself: every repository path cited in a source comment
exists, and no comment cites a document that is not in the repository (the original design notes
or the seed papers by their file numbers; cite docs/ and docs/reference/references.md instead).

Usage: check_references.py [REPO_ROOT]. Prints each dangling reference; exit 1 when any."""
import pathlib
import re
import sys

SCANNED = ["src", "include", "tests", "benchmarks", "verification/tools", "scripts"]
SUFFIXES = {".cpp", ".hpp", ".h", ".py", ".sh", ".in", ".txt"}
# A path into the repository: a top-level folder, then path characters, ending in a file suffix.
PATH = re.compile(r"(?<![\w/.<>-])((?:docs|verification|scripts|src|include|tests|benchmarks|cmake)/"
                  r"[A-Za-z0-9_./<>-]*\.(?:md|hpp|cpp|py|toml|csv|txt|sh|in))\b")
OUTSIDE = re.compile(r"DESIGN\.md|\bseed 00\d\b|\bseeds?/00\d")


def comments(path):
    """(line number, text) of the comment parts of a source file."""
    marker = "#" if path.suffix in {".py", ".sh", ".txt", ".in"} else "//"
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        stripped = line.strip()
        if marker in line or stripped.startswith(("*", "/*")):
            yield number, line


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    problems, checked = [], 0
    for folder in SCANNED:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in SUFFIXES or not path.is_file() or path.name == "check_references.py":
                continue
            for number, text in comments(path):
                where = f"{path.relative_to(root)}:{number}"
                if OUTSIDE.search(text):
                    problems.append(f"{where}: cites a document outside the repository: {text.strip()}")
                for cited in PATH.findall(text):
                    if "<" in cited or "*" in cited:
                        continue  # a pattern such as tests/<area>/<name>_test.cpp
                    checked += 1
                    if not (root / cited).exists():
                        problems.append(f"{where}: {cited} does not exist")
    for problem in problems:
        print(problem)
    print(f"{checked} references checked")
    print(f"{checked - len(problems)} passed, {len(problems)} failed")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
