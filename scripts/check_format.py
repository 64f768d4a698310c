#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Every tracked C++ file is formatted as .clang-format says (Google style, 100 columns).

The formatting is clang-format 14's, the version Debian 12 ships (scripts/setup.sh installs it):
another major version formats some constructs differently, so the check is skipped there (exit
77, ctest's SKIP_RETURN_CODE) rather than failing on a difference of tools. To format a file:
`clang-format -i FILE`.

Usage: check_format.py [REPO_ROOT]. Prints each file that differs; exit 1 when any."""
import pathlib
import re
import shutil
import subprocess
import sys

VERSION = 14


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
    tool = shutil.which("clang-format")
    if tool is None:
        print("clang-format is not installed (scripts/setup.sh installs it): check skipped")
        return 77
    banner = subprocess.run([tool, "--version"], capture_output=True, text=True).stdout
    major = re.search(r"version (\d+)", banner)
    if not major or int(major.group(1)) != VERSION:
        print(f"the formatting is clang-format {VERSION}'s; this is {banner.strip()}: check skipped")
        return 77
    files = subprocess.run(["git", "ls-files", "*.cpp", "*.hpp", "*.h"], cwd=root,
                           capture_output=True, text=True, check=True).stdout.split()
    # One call for every file: --dry-run names each line that would change, as a warning.
    report = subprocess.run([tool, "--dry-run", "--style=file", *files], cwd=root,
                            capture_output=True, text=True).stderr
    differ = sorted({m.group(1) for m in re.finditer(r"^(\S+?):\d+:\d+: warning", report, re.M)})
    for name in differ:
        print(f"{name}: not formatted (clang-format -i {name})")
    print(f"{len(files) - len(differ)} passed, {len(differ)} failed")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
