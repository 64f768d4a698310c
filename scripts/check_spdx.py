#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Every source file the repository tracks carries the licence's SPDX line (LICENSE, MIT).

C++ files start with `// SPDX-License-Identifier: MIT`; Python, shell, CMake and Makefiles with
`# SPDX-License-Identifier: MIT`, after a `#!` line when there is one.

Usage: check_spdx.py [REPO_ROOT] [--add]   (--add inserts the line where it is missing)
Prints each file without it; exit 1 when any (without --add)."""
import pathlib
import subprocess
import sys

LINE = "SPDX-License-Identifier: MIT"
CPP = {".cpp", ".hpp", ".h"}
HASH = {".py", ".sh", ".cmake"}
HASH_NAMES = {"CMakeLists.txt", "Makefile", "run"}


def comment_of(path):
    """The comment marker of a source file, or None for files that carry no licence line."""
    name = path.name
    if path.suffix in CPP or name.endswith((".hpp.in", ".cpp.in")):
        return "//"
    if path.suffix in HASH or name in HASH_NAMES or name.endswith(".py.in"):
        return "#"
    return None


def tracked_sources(root):
    listed = subprocess.run(["git", "ls-files"], cwd=root, capture_output=True, text=True,
                            check=True).stdout.splitlines()
    for name in listed:
        path = root / name
        if path.is_file() and comment_of(path):
            yield path


def add_line(path, marker):
    lines = path.read_text().splitlines(keepends=True)
    at = 1 if lines and lines[0].startswith("#!") else 0
    lines.insert(at, f"{marker} {LINE}\n")
    path.write_text("".join(lines))


def main(argv):
    add = "--add" in argv
    args = [a for a in argv if a != "--add"]
    root = pathlib.Path(args[0] if args else pathlib.Path(__file__).parent.parent).resolve()
    missing = 0
    for path in tracked_sources(root):
        head = path.read_text(errors="replace").splitlines()[:2]
        if any(LINE in line for line in head):
            continue
        if add:
            add_line(path, comment_of(path))
        else:
            print(f"{path.relative_to(root)}: no '{LINE}' line in its first two lines")
            missing += 1
    print(f"{missing} files without the SPDX line")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
