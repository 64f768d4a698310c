# SPDX-License-Identifier: MIT
"""The scene picture with matplotlib (docs/how-to/plot.md): the panels that the library builds from a
results JSON (include/catena/io/scene_picture.hpp, scene_picture_data) drawn on matplotlib axes.

Two users, one drawing:
- Result.plot(ax=None, modes=(1, 2, 3), plane="in-plane") in the package (catena/__init__.py);
- `catena plot ... --out FILE.png` and `--plot FILE.png`, which run this file as a script from the
  data dir (share/catena/plot.py): `plot.py --data PICTURE.json --out FILE.png`, or
  `plot.py --check-matplotlib` (exit 4 when matplotlib cannot be imported).

This file imports nothing of the package (it runs as a script, without the extension module) and
imports matplotlib only when drawing.
"""

import argparse
import importlib
import json
import sys
from typing import Any, Optional, Sequence, Union

#: One panel or the whole picture, as the library writes it (JSON objects).
Picture = dict[str, Any]

NO_MATPLOTLIB = 4
_MARKERS = {"circle": "o", "square": "s", "diamond": "D", "triangle-up": "^", "triangle-down": "v"}
#: Result.plot's plane argument -> the panel's id in the picture data
_PANELS = {"in-plane": "profile", "out-of-plane": "out-of-plane", "tension": "tension"}


def _values(items: Sequence[Optional[float]]) -> list[float]:
    """JSON numbers with null (a non-finite value) as NaN, so that matplotlib breaks the line."""
    return [float("nan") if v is None else v for v in items]


def _linestyle(dash: str, width: float) -> Union[str, tuple[float, tuple[float, ...]]]:
    if not dash:
        return "-"
    # matplotlib scales dash lengths by the line width; SVG's are in pixels.
    return (0.0, tuple(float(d) / max(width, 1.0) for d in dash.split(",")))


def draw_panel(ax: Any, panel: Picture) -> list[Any]:
    """Draws one panel of the picture data on `ax`; returns the Line2D objects of its series, in order."""
    for level in panel["levels"]:
        if level["y"] is not None:
            ax.axhline(level["y"], color=level["colour"], linestyle=_linestyle(level["dash"], 1.5),
                       linewidth=1.5, label=level["label"], gid=level["role"])
    lines = []
    for s in panel["series"]:
        (line,) = ax.plot(_values(s["x"]), _values(s["y"]), color=s["colour"],
                          linestyle=_linestyle(s["dash"], s["width"]), linewidth=s["width"],
                          label=s["label"] if s["in_legend"] else "_nolegend_", gid=s["role"])
        lines.append(line)
    for m in panel["markers"]:
        if m["x"] is not None and m["y"] is not None:
            ax.plot([m["x"]], [m["y"]], linestyle="none", marker=_MARKERS.get(m["shape"], "o"),
                    markerfacecolor=m["colour"], markeredgecolor="#222", markersize=7, label=m["label"],
                    gid=m["role"])
    ax.set_title(panel["title"], fontsize=10, loc="left")
    ax.set_xlabel(panel["x_label"])
    ax.set_ylabel(panel["y_label"])
    if panel["equal_axes"]:
        ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, color="#e4e4e4")
    if any(not h.get_label().startswith("_") for h in ax.get_lines()):
        ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    return lines


def panel_of(picture: Picture, plane: str) -> Picture:
    """The panel that `plane` names ("in-plane": the profile with the in-plane modes, "out-of-plane",
    "tension"); ValueError naming what the picture holds when it has no such panel."""
    if plane not in _PANELS:
        raise ValueError(f"plane: {plane!r}: expected one of {', '.join(map(repr, _PANELS))}")
    for panel in picture["panels"]:
        if panel["id"] == _PANELS[plane]:
            return dict(panel)
    held = ", ".join(p["id"] for p in picture["panels"])
    raise ValueError(f"plane: {plane!r}: the result has no out-of-plane mode shapes to draw (panels: {held})")


def draw_figure(picture: Picture) -> Any:
    """Every panel, stacked, with the title and the notes: a matplotlib Figure."""
    # Imported by name (untyped for mypy: matplotlib is optional and has no stubs here).
    matplotlib: Any = importlib.import_module("matplotlib")
    matplotlib.use("Agg")
    plt: Any = importlib.import_module("matplotlib.pyplot")

    heights = [3.4 if p["id"] == "profile" else 2.0 for p in picture["panels"]]
    figure, axes = plt.subplots(len(heights), 1, figsize=(11, sum(heights) + 1.2 + 0.2 * len(picture["notes"])),
                                gridspec_kw={"height_ratios": heights}, squeeze=False)
    for ax, panel in zip(axes[:, 0], picture["panels"]):
        draw_panel(ax, panel)
    figure.suptitle("\n".join(picture["title"]), fontsize=10, x=0.01, ha="left")
    if picture["notes"]:
        figure.text(0.01, 0.005, "\n".join(picture["notes"]), fontsize=7, va="bottom")
    figure.tight_layout(rect=(0, 0.02 + 0.015 * len(picture["notes"]), 1, 0.95))
    return figure


def main(argv: Optional[Sequence[str]] = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", help="picture data (JSON) written by catena")
    parser.add_argument("--out", help="PNG file to write")
    parser.add_argument("--check-matplotlib", action="store_true", help="exit 4 unless matplotlib imports")
    args = parser.parse_args(argv)
    try:
        importlib.import_module("matplotlib")  # the one dependency
    except ImportError as error:
        print(f"matplotlib cannot be imported: {error}", file=sys.stderr)
        return NO_MATPLOTLIB
    if args.check_matplotlib:
        return 0
    if not args.data or not args.out:
        parser.error("--data and --out are required")
    with open(args.data, encoding="utf-8") as file:
        picture = json.load(file)
    draw_figure(picture).savefig(args.out, dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
