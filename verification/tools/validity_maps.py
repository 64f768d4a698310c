#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Validity maps of the closed-form cable formulas (docs/explanation/validity-maps.md).

Reads the points.csv of a `catena sweep` over a `[taut_inclined]` scene (the SPEC files in
verification/sweeps/) and draws, for each model, the relative error of its first in-plane and first
out-of-plane frequency and the worst of its first six per plane, against shooting:

  - `asymptotic` and `airy`: the solvers' own columns in points.csv;
  - `string`: the taut-string formula w_n = (n pi / l) sqrt(T / M), both planes;
  - `irvine`: Irvine's symmetric in-plane equation tan x = x - (4 / lambda^2) x^3, x = w l / (2 c),
    with the antisymmetric in-plane modes at the string's even values w = 2 n pi c / l and the
    out-of-plane modes at the string's values (Irvine & Caughey 1974; Irvine 1981, ch. 3).

The formulas take the textbook inputs: l the chord between the supports, T = T0 = H / cos(phi) the
tension where the cable is parallel to its chord (for a level cable the horizontal tension H, for an
inclined one within O(eps^2) of the mean tension), M the normal mass per unit unstretched length,
c = sqrt(T / M), and lambda^2 the elasto-geometric parameter as `catena.dimensionless_groups`
reports it (EA eps^2 cos^2(phi) / T0, Irvine's (m g l / H)^2 l / (H L_e / EA) for a level cable to
within the strain and (sag/span)^2). They are computed from the points.csv columns
`groups.eps`, `groups.lambda2`, `groups.chord_angle_rad`, `groups.t0_n`, `groups.sag_parameter` and
`groups.taut_frequency_scale_rad_s`; `[taut_inclined]` has L = 1 m.

A point is grey (no value) where shooting did not converge, where its error estimate is above 1e-5
(too coarse a reference for the 1e-4 contour), or where the model declined or did not converge.

    python3 verification/tools/validity_maps.py build/report/validity --out build/report/figures \
        --summary summary.json
"""
import argparse
import csv
import json
import math
import pathlib
import re
import warnings

import numpy as np

REFERENCE = "shooting"
REFERENCE_MAX_ESTIMATE = 1e-5  # a reference 10x finer than the finest contour
MODES = 6
PLANES = ("inplane", "outofplane")
CONTOURS = (1e-4, 1e-3, 1e-2)
FORMULAS = ("string", "irvine")
SOLVER_MODELS = ("asymptotic", "airy")
MODELS = SOLVER_MODELS + FORMULAS
TITLES = {"asymptotic": "asymptotic (Grinfogel's eq. 21 and WKB)", "airy": "airy (linear-tension string)",
          "string": "taut string  w_n = (n pi / l) sqrt(T0 / M)",
          "irvine": "Irvine: tan x = x - 4 x^3 / lambda^2, antisymmetric and out of plane string"}
QUANTITIES = (("inplane1", "first in-plane frequency"), ("outofplane1", "first out-of-plane frequency"),
              ("worst6", "worst of the first six, both planes"))
# The map geometries: the SPEC file stems in verification/sweeps/ and their axes.
GEOMETRIES = {"level": ("lambda2", "sag_to_span"), "inclined": ("eps", "phi_deg")}
AXIS_LABELS = {"lambda2": "lambda^2 (Irvine)", "sag_to_span": "sag / span", "eps": "eps = W0 L / T0",
               "phi_deg": "chord inclination phi [deg]"}
LOG_AXES = {"lambda2", "sag_to_span", "eps"}
UNSTRETCHED_LENGTH_M = 1.0  # [taut_inclined]: Grinfogel's groups, L = 1 m


# --- the formulas ---------------------------------------------------------------------------------

def string_frequencies(chord_m, tension_n, mass_kg_per_m, count):
    """Taut string: w_n = (n pi / l) sqrt(T / M), n = 1..count [rad/s]."""
    c = math.sqrt(tension_n / mass_kg_per_m)
    return [n * math.pi * c / chord_m for n in range(1, count + 1)]


def irvine_symmetric_roots(lambda2, count):
    """The first `count` roots x > 0 of Irvine's tan x = x - (4 / lambda^2) x^3 (x = w l / 2c).

    f(x) = tan x - x + 4 x^3 / lambda^2 has f' = tan^2 x + 12 x^2 / lambda^2 > 0, so each branch
    ((2n-1) pi/2, (2n+1) pi/2) of tan holds exactly one root: it is bracketed there by
    g(x) = sin x - cos x (x - 4 x^3 / lambda^2), which is f cos x without the poles and is +-1 with
    opposite signs at the branch ends. lambda^2 = inf is the inextensible tan x = x."""
    from scipy.optimize import brentq  # noqa: PLC0415 (only the formulas need SciPy)

    cubic = 0.0 if math.isinf(lambda2) else 4.0 / lambda2

    def g(x):
        return math.sin(x) - math.cos(x) * (x - cubic * x ** 3)

    return [brentq(g, (2 * n - 1) * math.pi / 2, (2 * n + 1) * math.pi / 2, xtol=1e-15, rtol=1e-15)
            for n in range(1, count + 1)]


def irvine_inplane_frequencies(chord_m, tension_n, mass_kg_per_m, lambda2, count):
    """Irvine's in-plane frequencies, ascending: symmetric w = 2 x c / l (x the roots above) merged
    with the antisymmetric w = 2 n pi c / l [rad/s]."""
    c = math.sqrt(tension_n / mass_kg_per_m)
    symmetric = [2.0 * x * c / chord_m for x in irvine_symmetric_roots(lambda2, count)]
    antisymmetric = [2.0 * n * math.pi * c / chord_m for n in range(1, count + 1)]
    return sorted(symmetric + antisymmetric)[:count]


# --- the points -----------------------------------------------------------------------------------

def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def cable_of(row):
    """The formulas' inputs and the map's axes of one points.csv row of a [taut_inclined] sweep."""
    g = {key: number(row.get("groups." + key)) for key in (
        "eps", "lambda2", "chord_angle_rad", "t0_n", "sag_parameter", "taut_frequency_scale_rad_s")}
    length = UNSTRETCHED_LENGTH_M
    tan_phi = math.tan(g["chord_angle_rad"])
    # Gale's sag parameter b / sqrt(L^2 - h^2) with h = b tan(phi) gives the span b, then the chord.
    span = g["sag_parameter"] * length / math.sqrt(1.0 + (g["sag_parameter"] * tan_phi) ** 2)
    chord = span / math.cos(g["chord_angle_rad"])
    c = g["taut_frequency_scale_rad_s"] * length  # sqrt(T0 / M)
    mass = g["t0_n"] / (c * c)
    sag = number(row.get("statics.sag_to_span"))
    if not math.isfinite(sag) and g["chord_angle_rad"] == 0.0:
        # The level elastic catenary's midspan sag: (T_a - H) / W0 + W0 L^2 / (8 EA), with H = T0,
        # W0 = eps T0 / L and EA = lambda^2 T0 / eps^2 (closed form, when the sweep has no sag column).
        eps, lam2 = g["eps"], g["lambda2"]
        sag = length * ((math.sqrt(1.0 + eps * eps / 4.0) - 1.0) / eps + eps ** 3 / (8.0 * lam2)) / span
    return {"chord_m": chord, "tension_n": g["t0_n"], "mass_kg_per_m": mass, "lambda2": g["lambda2"],
            "eps": g["eps"], "phi_deg": math.degrees(g["chord_angle_rad"]), "sag_to_span": sag,
            "strain": g["eps"] ** 2 * math.cos(g["chord_angle_rad"]) ** 2 / g["lambda2"]}


def solver_modes(row, solver, plane, max_estimate=math.inf):
    """The solver's first MODES frequencies in a plane; None if it did not converge, misses one or
    estimates an error above max_estimate."""
    if row.get(solver + ".status") != "converged":
        return None
    values = []
    for k in range(1, MODES + 1):
        stem = f"{solver}.{plane}.mode{k}."
        omega, estimate = number(row.get(stem + "omega_rad_s")), number(row.get(stem + "relative_error_estimate"))
        if not math.isfinite(omega) or omega <= 0.0 or not estimate <= max_estimate:
            return None
        values.append(omega)
    return values


def model_modes(row, model, cable):
    if model in SOLVER_MODELS:
        return {plane: solver_modes(row, model, plane) for plane in PLANES}
    args = (cable["chord_m"], cable["tension_n"], cable["mass_kg_per_m"])
    if not (all(math.isfinite(a) and a > 0.0 for a in args) and cable["lambda2"] > 0.0):
        return {plane: None for plane in PLANES}  # a point without statics (refused): grey
    string = string_frequencies(*args, MODES)
    if model == "string":
        return {"inplane": string, "outofplane": string}
    return {"inplane": irvine_inplane_frequencies(*args, cable["lambda2"], MODES), "outofplane": string}


def errors(reference, modes):
    """{quantity: relative error or nan (grey)} of one point."""
    def rel(plane, k):
        if reference[plane] is None or modes[plane] is None:
            return math.nan
        return abs(modes[plane][k] - reference[plane][k]) / reference[plane][k]

    every = [rel(plane, k) for plane in PLANES for k in range(MODES)]
    return {"inplane1": rel("inplane", 0), "outofplane1": rel("outofplane", 0),
            "worst6": max(every) if all(math.isfinite(e) for e in every) else math.nan}


def read_map(points_csv):
    """The axes and errors of every point: {"cable": [...], model: {quantity: np.array}}."""
    cables, table = [], {m: {q: [] for q, _ in QUANTITIES} for m in MODELS}
    with open(points_csv, newline="") as f:
        for row in csv.DictReader(f):
            cable = cable_of(row)
            reference = {plane: solver_modes(row, REFERENCE, plane, REFERENCE_MAX_ESTIMATE) for plane in PLANES}
            cables.append(cable)
            for model in MODELS:
                for quantity, value in errors(reference, model_modes(row, model, cable)).items():
                    table[model][quantity].append(value)
    if not cables:
        raise ValueError(f"{points_csv}: no points")
    return {"cable": cables, **{m: {q: np.array(v) for q, v in table[m].items()} for m in MODELS}}


# --- drawing --------------------------------------------------------------------------------------

def triangulation(x, y, log_x, log_y):
    """Delaunay in the plotted (log or linear) coordinates, so that log-spaced grids triangulate into
    their cells; returned in data coordinates for drawing on log axes."""
    import matplotlib.tri as mtri  # noqa: PLC0415

    grid = mtri.Triangulation(np.log10(x) if log_x else x, np.log10(y) if log_y else y)
    return mtri.Triangulation(x, y, triangles=grid.triangles)


def draw_panel(ax, tri, error, title):
    """Heat map of log10(error) with contours at CONTOURS; grey where no value. Returns the image
    and the contour set (None, None when every point is grey)."""
    import matplotlib.tri as mtri  # noqa: PLC0415

    valid = np.isfinite(error)
    level = np.log10(np.clip(np.where(valid, error, 1.0), 1e-16, None))
    masked = mtri.Triangulation(tri.x, tri.y, triangles=tri.triangles,
                                mask=np.any(~valid[tri.triangles], axis=1))
    ax.set_facecolor("0.75")
    image = lines = None
    if not masked.mask.all():
        faces = level[masked.triangles].mean(axis=1)  # flat shading: gouraud ignores the mask
        image = ax.tripcolor(masked, facecolors=faces, cmap="viridis", vmin=-8.0, vmax=0.0,
                             edgecolors="none")
        with warnings.catch_warnings():  # a map wholly inside one band has no contour: not an error
            warnings.simplefilter("ignore", UserWarning)
            lines = ax.tricontour(masked, level, levels=np.log10(CONTOURS), colors="w",
                                  linewidths=(0.8, 1.1, 1.6), linestyles=("dotted", "dashed", "solid"))
        if lines.allsegs and any(len(s) for s in lines.allsegs):
            ax.clabel(lines, fmt={v: f"{c:g}" for v, c in zip(lines.levels, CONTOURS)}, fontsize=7)
    ax.set_title(title, fontsize=9)
    return image, lines


def draw_figure(data, geometry, model, out_dir):
    """validity-map-<geometry>-<model>.png: three panels; returns (file, caption)."""
    import matplotlib  # noqa: PLC0415

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: PLC0415

    xkey, ykey = GEOMETRIES[geometry]
    x = np.array([c[xkey] for c in data["cable"]])
    y = np.array([c[ykey] for c in data["cable"]])
    tri = triangulation(x, y, xkey in LOG_AXES, ykey in LOG_AXES)
    fig, axes = plt.subplots(1, 3, figsize=(13.5, 4.2), sharey=True, layout="constrained")
    image = None
    for ax, (quantity, label) in zip(axes, QUANTITIES):
        image = draw_panel(ax, tri, data[model][quantity], label)[0] or image
        ax.set_xscale("log" if xkey in LOG_AXES else "linear")
        ax.set_yscale("log" if ykey in LOG_AXES else "linear")
        ax.set_xlabel(AXIS_LABELS[xkey])
        if geometry == "level":  # the physical corner: static strain T0/EA = 1 % along this line
            strain = np.array([c["strain"] for c in data["cable"]])
            with warnings.catch_warnings():  # a map wholly on one side of it has no line
                warnings.simplefilter("ignore", UserWarning)
                ax.tricontour(tri, np.log10(strain), levels=[-2.0], colors="r", linewidths=0.8,
                              linestyles="dashdot")
    axes[0].set_ylabel(AXIS_LABELS[ykey])
    if image is not None:
        bar = fig.colorbar(image, ax=list(axes), shrink=0.95, aspect=30)
        bar.set_label("log10 relative error against shooting")
    fig.suptitle(f"{geometry} cable: {TITLES[model]}", fontsize=10)
    name = f"validity-map-{geometry}-{model}.png"
    fig.savefig(pathlib.Path(out_dir) / name, dpi=100)
    plt.close(fig)
    where = ("over (lambda^2, sag/span), phi = 0; red dash-dot: static strain T0/EA = 1 % (above it, "
             "stretchier than most lines)" if geometry == "level" else "over (eps, phi) at fixed lambda^2")
    caption = (f"Validity map, {geometry} cable, {TITLES[model]}: relative error of the first in-plane, "
               f"first out-of-plane and worst of the first six frequencies per plane against shooting, "
               f"{where}. White contours at 1e-4 (dotted), 1e-3 (dashed), 1e-2 (solid); grey: no value "
               f"(the model declined or did not converge, or shooting's estimate is above "
               f"{REFERENCE_MAX_ESTIMATE:g}). {len(x)} points (validity/{geometry}/points.csv).")
    return name, caption


# --- where each model holds -----------------------------------------------------------------------

# Per geometry: the axis set directly by the sweep (one column of the map per value) and the one
# along which a model degrades (sag, eps): a model "holds to 1 % up to y" in a column when every
# point from the column's smallest y up to y is within 1 % (a grey point ends the run too).
COLUMNS = {"level": ("lambda2", "sag_to_span"), "inclined": ("phi_deg", "eps")}
THRESHOLDS = (1e-2, 1e-3)
# The columns the docs tabulate (the nearest grid values are taken).
TABLE_COLUMNS = {"level": (0.1, 1.0, 10.0, 4 * math.pi ** 2, 100.0, 1000.0),
                 "inclined": (0.0, 15.0, 30.0, 45.0, 60.0, 85.0)}


def holds_up_to(data, geometry, model, quantity, threshold):
    """[(column value, largest y up to which the model holds or None where its first y does not,
    what ends the run: "error" above the threshold, "grey" no value, "edge" the map's end)]."""
    column, along = COLUMNS[geometry]
    groups = {}
    for cable, error in zip(data["cable"], data[model][quantity]):
        groups.setdefault(float(f"{cable[column]:.9g}"), []).append((cable[along], error))
    result = []
    for value in sorted(groups):
        last, end = None, "edge"
        for y, error in sorted(groups[value]):
            if not error <= threshold:
                end = "error" if math.isfinite(error) else "grey"
                break
            last = y
        result.append((value, last, end))
    return result


def summarize(data, geometry):
    """{model: {quantity: {threshold: {"columns": [[x, y or null]], "everywhere_up_to": y}}}}."""
    out = {}
    for model in MODELS:
        out[model] = {}
        for quantity, _ in QUANTITIES:
            out[model][quantity] = {}
            for threshold in THRESHOLDS:
                columns = holds_up_to(data, geometry, model, quantity, threshold)
                ys = [y for _, y, _ in columns]
                everywhere = None if any(y is None for y in ys) else min(ys)
                out[model][quantity][f"{threshold:g}"] = {"columns": [list(c) for c in columns],
                                                          "everywhere_up_to": everywhere}
    return out


def prose_notes(data, summary, geometry):
    """Lines for the docs' prose: the columns where each model holds at all, and (level) the static
    strain T0/EA at the string's out-of-plane boundaries."""
    column, along = COLUMNS[geometry]
    lines = []
    for model in MODELS:
        for quantity, label in QUANTITIES:
            for threshold in THRESHOLDS:
                columns = summary[model][quantity][f"{threshold:g}"]["columns"]
                held = [x for x, y, _ in columns if y is not None]
                if held and len(held) < len(columns):
                    lines.append(f"- {model}, {label}, {threshold:g}: holds somewhere only for {column} in "
                                 f"[{min(held):.3g}, {max(held):.3g}] ({len(held)} of {len(columns)} columns)")
    if geometry == "level":
        strain = {(float(f"{c[column]:.9g}"), c[along]): c["strain"] for c in data["cable"]}
        for threshold in THRESHOLDS:
            columns = summary["string"]["outofplane1"][f"{threshold:g}"]["columns"]
            at = [strain[(x, y)] for x, y, _ in columns if y is not None and (x, y) in strain]
            lines.append(f"- string out of plane, {threshold:g}: static strain T0/EA at the boundary "
                         f"from {min(at):.3g} to {max(at):.3g}; at {column} = {columns[0][0]:.3g}: "
                         f"{strain[(columns[0][0], columns[0][1])]:.3g}")
    return "\n".join(lines)


def table(summary, geometry, picks):
    """Markdown: per model and quantity, the largest y holding to 1 % and 0.1 % at the grid columns
    nearest each pick; '*' where the model declines beyond it (grey), '+' where it holds to the
    map's edge."""
    column, along = COLUMNS[geometry]
    any_entry = summary[MODELS[0]][QUANTITIES[0][0]][f"{THRESHOLDS[0]:g}"]["columns"]
    xs = np.array([x for x, _, _ in any_entry])
    chosen = [float(xs[np.argmin(np.abs(np.log(xs / p) if column in LOG_AXES else xs - p))]) for p in picks]
    head = " | ".join(f"{x:.3g}: 1 % / 0.1 %" for x in chosen)
    lines = [f"| model, frequency | {AXIS_LABELS[column]} = {head} | every {column} of the map |",
             "|---|" + "---|" * (len(chosen) + 1)]
    for model in MODELS:
        if all(entry[1] is None and entry[2] == "grey" for quantity, _ in QUANTITIES for threshold in THRESHOLDS
               for entry in summary[model][quantity][f"{threshold:g}"]["columns"]):
            lines.append(f"| {model}: declines every point of the map |" + " |" * (len(chosen) + 1))
            continue
        for quantity, label in QUANTITIES:
            cells = []
            for x in chosen:
                pair = []
                for threshold in THRESHOLDS:
                    entry = {a: (b, end) for a, b, end in summary[model][quantity][f"{threshold:g}"]["columns"]}
                    y, end = entry[x]
                    pair.append("-" if y is None else f"{y:.3g}" + {"grey": "*", "edge": "+"}.get(end, ""))
                cells.append(" / ".join(pair))
            everywhere = [summary[model][quantity][f"{t:g}"]["everywhere_up_to"] for t in THRESHOLDS]
            cells.append(" / ".join("-" if y is None else f"{y:.3g}" for y in everywhere))
            lines.append(f"| {model}, {label} | " + " | ".join(cells) + " |")
    return f"{AXIS_LABELS[along]} up to which each model holds:\n\n" + "\n".join(lines)


# --- the report's entry point ---------------------------------------------------------------------

def draw_all(validity_dir, out_dir, models=MODELS):
    """Every map whose sweep output exists: validity_dir/<geometry>/points.csv. Returns
    [(file, caption)] and the notes of maps not drawn."""
    figures, notes = [], []
    for geometry in GEOMETRIES:
        points = pathlib.Path(validity_dir) / geometry / "points.csv"
        if not points.is_file():
            notes.append(f"validity map '{geometry}' not drawn: {points} not found (run catena sweep "
                         f"verification/sweeps/{geometry}-coarse.toml --out {points.parent})")
            continue
        data = read_map(points)
        for model in models:
            if not any(np.isfinite(data[model][q]).any() for q, _ in QUANTITIES):
                notes.append(f"validity map '{geometry}' of {model} not drawn: no point has a value "
                             f"(e.g. airy declines every level cable)")
                continue
            figures.append(draw_figure(data, geometry, model, out_dir))
    return figures, notes


def rounded(value):
    """The summary with its floats at 6 significant digits."""
    if isinstance(value, dict):
        return {k: rounded(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [rounded(v) for v in value]
    return float(f"{value:.6g}") if isinstance(value, float) else value


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("validity", help="directory holding <geometry>/points.csv (level, inclined)")
    parser.add_argument("--out", help="draw the maps into this directory")
    parser.add_argument("--summary", help="write where each model holds (JSON) to this file")
    parser.add_argument("--tables", action="store_true", help="print the docs' tables (markdown)")
    args = parser.parse_args()
    if args.out:
        pathlib.Path(args.out).mkdir(parents=True, exist_ok=True)
        figures, notes = draw_all(args.validity, args.out)
        print("\n".join(notes + [f"drew {name}" for name, _ in figures]))
    summaries = {}
    for geometry in GEOMETRIES:
        points = pathlib.Path(args.validity) / geometry / "points.csv"
        if points.is_file() and (args.summary or args.tables):
            data = read_map(points)
            summaries[geometry] = {"points": len(data["cable"]), "maps": summarize(data, geometry)}
            if args.tables:
                print(f"## {geometry} ({len(data['cable'])} points)\n")
                print(table(summaries[geometry]["maps"], geometry, TABLE_COLUMNS[geometry]) + "\n")
                print(prose_notes(data, summaries[geometry]["maps"], geometry) + "\n")
    if args.summary:
        with open(args.summary, "w") as f:
            # One line per model and frequency; 6 significant digits, the grid's own resolution
            # being far coarser.
            text = json.dumps(rounded(summaries), indent=1)
            text = re.sub(r"\[\s*([^\[\]]*?)\s*\]", lambda m: "[" + re.sub(r"\s+", " ", m.group(1)) + "]", text)
            f.write(text + "\n")


if __name__ == "__main__":
    main()
