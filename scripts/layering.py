#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Which folder includes which: a Markdown table for docs/contributing/architecture.md ("Layers").

Scans the #include "..." lines of src/ and include/catena/, maps every file and every included
header to its layer folder (core, models, statics, solvers, verification, io, cli; a folder's
internal/ belongs to it), and prints a table of include counts, including folder by row, included
folder by column. Data must flow one way, core -> models -> statics -> solvers -> verification ->
io -> cli: an include of a later layer from an earlier one is flagged in the table and listed
below it, as is a public header (include/) that includes a private one (src/). Solvers stay
independent: a file in src/solvers/<solver>/ may include its own folder and src/solvers/common/,
never another solver's folder (docs/contributing/architecture.md, "Folders"); such an include is flagged too.

Usage: python3 scripts/layering.py [REPOSITORY_ROOT]   (exit status 1 when something is flagged)
"""
import pathlib
import re
import sys

LAYERS = ["core", "models", "statics", "solvers", "verification", "io", "cli"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
SOURCE_SUFFIXES = {".hpp", ".cpp", ".h", ".cc"}
# Headers generated at configure time (cmake/*.in) and the layer that owns them.
GENERATED = {"catena/build_info.hpp": "core"}


def layer_of_file(path, root):
    """The layer of a file under src/ or include/catena/, or None."""
    parts = path.relative_to(root).parts
    if parts[0] == "include" and len(parts) > 2 and parts[1] == "catena":
        return parts[2] if parts[2] in LAYERS else None
    if parts[0] == "src" and len(parts) > 1:
        return parts[1] if parts[1] in LAYERS else None
    return None


def layer_of_include(name):
    """The layer of an included header ("catena/solvers/x.hpp", "solvers/fe/y.hpp"), or
    None for anything else (a header next to the includer, a third-party header)."""
    if name in GENERATED:
        return GENERATED[name]
    parts = name.split("/")
    if parts[0] == "catena" and len(parts) > 2:
        parts = parts[1:]
    return parts[0] if len(parts) > 1 and parts[0] in LAYERS else None


def scan(root):
    """Yields (file, line number, includer layer, included layer, header, private header?)."""
    for top in ("src", "include"):
        for path in sorted((root / top).rglob("*")):
            if path.suffix not in SOURCE_SUFFIXES:
                continue
            includer = layer_of_file(path, root)
            if includer is None:
                continue
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                header = match.group(1)
                included = layer_of_include(header)
                if included is None:
                    continue
                private = not header.startswith("catena/")
                yield path.relative_to(root), number, includer, included, header, private


def solver_folder(parts):
    """The solver folder of a path's parts ("src", "solvers", "fe", ...) or of an include's
    ("solvers", "fe", ...): the folder name, or None outside src/solvers/<solver>/."""
    if parts and parts[0] == "src":
        parts = parts[1:]
    if len(parts) > 2 and parts[0] == "solvers" and parts[1] != "common":
        return parts[1]
    return None


def crosses_solvers(path, header):
    """True when a solver's file includes another solver's private file."""
    own = solver_folder(path.parts)
    other = solver_folder(tuple(header.split("/")))
    return own is not None and other is not None and own != other


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
    counts = {}
    flagged = []
    for path, number, includer, included, header, private in scan(root):
        counts[(includer, included)] = counts.get((includer, included), 0) + 1
        upward = LAYERS.index(included) > LAYERS.index(includer)
        public_to_private = path.parts[0] == "include" and private
        crossing = crosses_solvers(path, header)
        if upward or public_to_private or crossing:
            why = ("against the layer order" if upward else "public header includes a private one"
                   if public_to_private else "a solver includes another solver's file")
            flagged.append(f"- `{path}:{number}` includes `{header}` ({includer} -> {included}: {why})")
    upward_pairs = {(a, b) for (a, b) in counts if LAYERS.index(b) > LAYERS.index(a)}

    print("| includes \u2193 \u2192 | " + " | ".join(LAYERS) + " |")
    print("|---" * (len(LAYERS) + 1) + "|")
    for a in LAYERS:
        cells = []
        for b in LAYERS:
            n = counts.get((a, b), 0)
            cells.append("" if n == 0 else (f"**{n} !**" if (a, b) in upward_pairs else str(n)))
        print(f"| **{a}** | " + " | ".join(cells) + " |")
    print()
    print("Rows include columns (number of `#include` lines); `!` marks includes against the order "
          + " -> ".join(LAYERS) + ".")
    print()
    if flagged:
        print("Flagged includes:")
        print()
        print("\n".join(flagged))
    else:
        print("No include goes against the layer order, no public header includes a private one, "
              "and no solver includes another solver's files.")
    return 1 if flagged else 0


if __name__ == "__main__":
    sys.exit(main())
