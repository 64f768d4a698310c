#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Figures of the Catena report, drawn with matplotlib from the results JSON of `catena verify`.

    /usr/bin/python3 verification/tools/figures.py --results build/report/report.json \
        --published verification/reference/published --out build/report/figures \
        --time-vs-error benchmarks/results/time-vs-error.csv [--validity build/report/validity]

Writes PNG files and index.json ([{file, caption}], in report order). A figure whose scenes are
not in the results (e.g. a filtered run) is skipped. Published points are read from the
transcribed tables and overlaid as open markers. The validity maps (validity_maps.py) are drawn from
the `catena sweep` outputs in --validity (default: the report's DIR/validity/<geometry>/points.csv).
"""
import argparse
import csv
import json
import math
import os
import pathlib
import sys
import types

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {"shooting": ("-", "o", "C0"), "fe": ("--", "s", "C1"), "frobenius": (":", "^", "C2"),
         "asymptotic": ("-.", "v", "C3"), "airy": ((0, (3, 1, 1, 1)), "D", "C4")}
# The data dir (share/catena, or <build>/share/catena where this script is a link): the directory
# the script was started from, links not resolved.
DATA_DIR = pathlib.Path(os.path.abspath(sys.argv[0])).parent


def load_keys():
    """The JSON key names (src/io/results_keys.txt, the list the C++ writer uses too): the generated
    module results_keys.py of the data dir, or, run from the source tree, the list itself."""
    sys.path.insert(0, str(DATA_DIR))
    try:
        import results_keys
        return results_keys
    except ImportError:
        listing = pathlib.Path(__file__).resolve().parents[2] / "src" / "io" / "results_keys.txt"
        names = [line.strip() for line in listing.read_text().splitlines()
                 if line.strip() and not line.startswith("#")]
        return types.SimpleNamespace(**{name: name for name in names})


K = load_keys()
PLANES = {K.inplane: "in-plane", K.outofplane: "out-of-plane"}


def read_table(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#") and line.strip()))


class Figures:
    def __init__(self, results, published, out):
        self.scenes = results[K.scenes]
        self.published = pathlib.Path(published)
        self.out = pathlib.Path(out)
        self.index = []

    def save(self, fig, name, caption):
        fig.tight_layout()
        fig.savefig(self.out / name, dpi=110)
        plt.close(fig)
        self.index.append({K.file: name, K.caption: caption})

    def sweep(self, prefix):
        """Scenes of one sweep (name starts with prefix + '['), sorted by the swept value."""
        members = [s for s in self.scenes if s[K.name].startswith(prefix + "[") and s.get(K.sweep)]
        return sorted(members, key=lambda s: s[K.sweep][K.value])

    @staticmethod
    def modes(scene, solver, plane):
        out = scene[K.solvers].get(solver, {})
        return out.get(plane, {}).get(K.modes, []) if out.get(K.summary, {}).get(K.termination) in (
            "converged", "no-convergence") else []

    def solvers_in(self, scenes):
        names = []
        for s in scenes:
            for name, out in s[K.solvers].items():
                if out[K.summary][K.termination] in ("converged", "no-convergence") and name not in names:
                    names.append(name)
        return [n for n in STYLE if n in names]

    def frequency_sweep(self, prefix, unit_key, name, caption, published_rows=None, modes_shown=None):
        scenes = self.sweep(prefix)
        if not scenes:
            return
        fig, ax = plt.subplots(figsize=(7.5, 4.8))
        x = [s[K.sweep][K.value] for s in scenes]
        for solver in self.solvers_in(scenes):
            ls, marker, color = STYLE[solver]
            count = max(len(self.modes(s, solver, K.inplane)) for s in scenes)
            for k in range(count if modes_shown is None else min(count, modes_shown)):
                y = [self.modes(s, solver, K.inplane)[k][unit_key] if k < len(self.modes(s, solver, K.inplane))
                     else math.nan for s in scenes]
                ax.plot(x, y, linestyle=ls, marker=marker, markersize=3, color=color,
                        label=solver if k == 0 else None)
        for label, rows, marker in published_rows or []:
            ax.plot([r[0] for r in rows], [r[1] for r in rows], linestyle="none", marker=marker, markersize=8,
                    markerfacecolor="none", color="k", label=label)
        ax.set_xscale("log")
        ax.set_xlabel("lambda^2")
        ax.set_ylabel("kL/pi" if unit_key == K.k_l_over_pi else unit_key)
        ax.axvline(4 * math.pi ** 2, color="0.7", linewidth=0.8)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        self.save(fig, name, caption)

    def grinfogel(self):
        self.frequency_sweep("irvine-horizontal", K.k_l_over_pi, "irvine-horizontal.png",
                             "Grinfogel Fig. 1.2.5 regenerated: in-plane kL/pi against lambda^2 of a horizontal "
                             "cable (eps = 0.01); symmetric and antisymmetric families cross at lambda^2 = 4 pi^2 "
                             "(grey line).")
        self.frequency_sweep("inclined-crossover", K.k_l_over_pi, "inclined-crossover.png",
                             "Grinfogel Fig. 1.2.6.2 regenerated: in-plane kL/pi against lambda^2 of an inclined "
                             "cable (phi = 20 deg, eps = 0.1): the families veer instead of crossing.")
        table = self.published / "grinfogel-1984-table-2-2-frequencies.csv"
        rows = read_table(table) if table.exists() else []
        for eps, phi in [("0.18", "23.46"), ("0.49", "45.0")]:
            sel = [r for r in rows if r["eps"] == eps and r["phi_deg"] == phi]
            exact = [(float(r["lambda2"]), float(r["exact"])) for r in sel]
            approx = [(float(r["lambda2"]), float(r["approx"])) for r in sel]
            self.frequency_sweep(f"grinfogel-curve-eps{eps}-phi{phi}", K.k_l_over_pi,
                                 f"grinfogel-eps{eps}-phi{phi}.png",
                                 f"Grinfogel Table 2.2 / Fig. 2.2, eps = {eps}, phi = {phi} deg: our solvers' "
                                 f"kL/pi against lambda^2, with the published 'exact' (circles) and 'approx' "
                                 f"(squares) points.",
                                 [("published exact", exact, "o"), ("published approx", approx, "s")])

    def mode_shapes(self):
        scenes = [s for s in self.sweep("inclined-crossover") if s[K.sweep][K.value] in (10.0, 45.0, 120.0)]
        if not scenes:
            return
        fig, axes = plt.subplots(len(scenes), 2, figsize=(9, 2.6 * len(scenes)), squeeze=False)
        for row, scene in enumerate(scenes):
            for k in range(2):
                ax = axes[row][k]
                for solver in self.solvers_in([scene]):
                    modes = self.modes(scene, solver, K.inplane)
                    if k < len(modes) and K.shape in modes[k] and K.w in modes[k][K.shape]:
                        shape = modes[k][K.shape]
                        ls, _, color = STYLE[solver]
                        s = [v / shape[K.s_m][-1] for v in shape[K.s_m]]
                        ax.plot(s, shape[K.w], linestyle=ls, color=color, label=solver)
                ax.set_title(f"lambda^2 = {scene[K.sweep][K.value]:g}, mode {k + 1}: w(s)", fontsize=9)
                ax.grid(alpha=0.3)
                if row == 0 and k == 0:
                    ax.legend(fontsize=7)
        axes[-1][0].set_xlabel("s / L")
        axes[-1][1].set_xlabel("s / L")
        self.save(fig, "mode-shapes.png",
                  "Grinfogel Figs. 3.4.1.x regenerated: normal displacement w(s) of the first two in-plane modes "
                  "(phi = 20 deg, eps = 0.1) below, near and above cross-over, every solver overlaid "
                  "(normalised to max |w| = 1).")

    def dynamic_tension(self):
        scenes = self.sweep("inclined-crossover")
        if not scenes:
            return
        fig, ax = plt.subplots(figsize=(7.5, 4.5))
        x = [s[K.sweep][K.value] for s in scenes]
        drawn = False
        for solver in self.solvers_in(scenes):
            ls, marker, color = STYLE[solver]
            for k in range(2):
                y = []
                for s in scenes:
                    m = self.modes(s, solver, K.inplane)
                    y.append(m[k].get(K.max_abs_tension_n, math.nan) if k < len(m) else math.nan)
                if all(math.isnan(v) for v in y):
                    continue
                drawn = True
                ax.plot(x, y, linestyle=ls, marker=marker, markersize=3, color=color,
                        label=f"{solver}, mode {k + 1}")
        if not drawn:
            plt.close(fig)
            return
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("lambda^2")
        ax.set_ylabel("max |tau| per unit max |w| [N/m]")
        ax.axvline(4 * math.pi ** 2, color="0.7", linewidth=0.8)
        ax.legend(fontsize=7, ncol=2)
        ax.grid(alpha=0.3)
        self.save(fig, "dynamic-tension.png",
                  "Grinfogel Figs. 4.3.2/4.3.3 regenerated: modal dynamic tension against lambda^2 (phi = 20 deg, "
                  "eps = 0.1); the tension of the first modes is amplified near cross-over.")

    def gale_frequencies(self):
        for table, label, plane in [("gale-1976-table-B3-inplane.csv", "b-3", K.inplane),
                                    ("gale-1976-table-B4-outofplane.csv", "b-4", K.outofplane)]:
            path = self.published / table
            if not path.exists():
                continue
            rows = read_table(path)
            for hb in sorted({r["h_over_b"] for r in rows}, key=float):
                # Gale's undamped figures: a damped variant of a table scene is not one of his points.
                scenes = [s for s in self.scenes if s[K.name].startswith(f"gale-{label}-hb{float(hb):.2f}-sag")
                          and "damped" not in s.get(K.tags, [])]
                if not scenes:
                    continue
                scenes.sort(key=lambda s: s[K.groups][K.gale][K.sag_param] or 0)
                fig, ax = plt.subplots(figsize=(7, 4.5))
                for solver in self.solvers_in(scenes):
                    ls, marker, color = STYLE[solver]
                    for k in range(6):
                        pts = [(s[K.groups][K.gale][K.sag_param], self.modes(s, solver, plane)[k][K.gale_ratio])
                               for s in scenes if k < len(self.modes(s, solver, plane))]
                        if pts:
                            ax.plot(*zip(*pts), linestyle=ls, marker=marker, markersize=3, color=color,
                                    label=solver if k == 0 else None)
                pub = [(float(r["sag_param"]), float(r[f"w{k}"])) for r in rows if r["h_over_b"] == hb
                       for k in range(1, 7) if r[f"w{k}"]]
                ax.plot(*zip(*pub), linestyle="none", marker="o", markersize=7, markerfacecolor="none", color="k",
                        label=f"Gale Table {label.upper()}")
                ax.set_xlabel("sag parameter b / sqrt(l^2 - h^2)")
                ax.set_ylabel("w / sqrt(g/a)")
                ax.set_yscale("log")
                ax.legend(fontsize=8)
                ax.grid(alpha=0.3)
                self.save(fig, f"gale-{label}-hb{float(hb):.2f}.png",
                          f"Gale Figs. 3.2-3.11 regenerated: {PLANES[plane]} frequency ratios of the first six "
                          f"modes against the sag parameter, h/b = {hb}; published Table {label.upper()} values as "
                          f"open circles.")

    def gale_forced(self):
        table = self.published / "gale-1976-table-C2-forced-max-tension.csv"
        rows = read_table(table) if table.exists() else []
        for scene in [s for s in self.scenes if s[K.name].startswith("gale-c-2-curve-")]:
            H = scene[K.statics][K.horizontal_force_n]
            scale = scene[K.groups][K.gale][K.frequency_scale_rad_s]
            fig, ax = plt.subplots(figsize=(7.5, 4.5))
            for solver in self.solvers_in([scene]):
                forced = scene[K.solvers][solver].get(K.forced, [])
                pts = [(f[K.omega_rad_s] / scale, f[K.max_abs_tension_n] / H) for f in forced
                       if not f.get(K.diagnostic) and f.get(K.max_abs_tension_n) is not None]
                if pts:
                    ls, _, color = STYLE[solver]
                    ax.plot(*zip(*pts), linestyle=ls, color=color, label=solver)
            hb = f"{scene[K.groups][K.gale][K.h_over_b]:.2f}"
            sag = scene[K.name].split("-sag")[-1]
            pub = [(float(r["wf"]), float(r["tmax"])) for r in rows
                   if f"{float(r['h_over_b']):.2f}" == hb and r["sag_param"] == sag]
            if pub:
                ax.plot(*zip(*pub), linestyle="none", marker="o", markerfacecolor="none", color="k",
                        label="Gale Table C-2")
            ax.set_yscale("log")
            ax.set_xlabel("forcing frequency w / sqrt(g/a)")
            ax.set_ylabel("max |dynamic tension| / H")
            ax.legend(fontsize=8)
            ax.grid(alpha=0.3)
            self.save(fig, f"{scene[K.name]}.png",
                      f"Gale Figs. 3.14-3.15 regenerated: maximum dynamic tension along the cable against the "
                      f"forcing frequency, tangential end motion 0.01 a, h/b = {hb}, sag parameter {sag}; "
                      f"Table C-2 as open circles.")

    def model_error(self):
        """Actual error of asymptotic and airy against the most accurate exact solver that ran (the
        rule of the report's model-error table, src/io/report/model_error.cpp), against eps."""
        models, reference_order = ("asymptotic", "airy"), ("frobenius", "shooting", "fe")
        fig, axes = plt.subplots(2, 2, figsize=(9, 6.5), squeeze=False, sharex=True, sharey=True)
        drawn = False
        for row, plane in enumerate((K.inplane, K.outofplane)):
            for col, model in enumerate(models):
                ax, points = axes[row][col], []
                for scene in self.scenes:
                    reference = next((r for r in reference_order if self.modes(scene, r, plane)), None)
                    eps = scene.get(K.groups, {}).get(K.eps)
                    if reference is None or not eps:
                        continue
                    exact = {m[K.index]: m[K.omega_rad_s] for m in self.modes(scene, reference, plane)}
                    for m in self.modes(scene, model, plane):
                        if m[K.index] in exact and m[K.omega_rad_s] is not None and exact[m[K.index]]:
                            error = abs(m[K.omega_rad_s] - exact[m[K.index]]) / abs(exact[m[K.index]])
                            if error > 0:
                                points.append((eps, error))
                if points:
                    drawn = True
                    _, marker, color = STYLE[model]
                    ax.plot(*zip(*points), linestyle="none", marker=marker, markersize=3, color=color, alpha=0.6)
                    guide = [1e-3, 1e-2, 1e-1, 1.0]
                    ax.plot(guide, [0.1 * e * e for e in guide], color="0.5", linewidth=0.8, label="0.1 eps^2")
                    ax.legend(fontsize=7)
                ax.set_xscale("log")
                ax.set_yscale("log")
                ax.grid(alpha=0.3)
                ax.set_title(f"{model}, {PLANES[plane]}", fontsize=9)
        if not drawn:
            plt.close(fig)
            return
        for ax in axes[-1]:
            ax.set_xlabel("eps = W0 L / T0")
        for row in axes:
            row[0].set_ylabel("relative error of omega")
        self.save(fig, "model-error.png",
                  "Measured model error of the analytic solvers: each mode's relative error against the most "
                  "accurate exact solver that ran (frobenius, else shooting, else fe), against eps, every scene "
                  "of the run; the grey line is 0.1 eps^2. Fitted orders in the model-error table.")


def damped_resonance(figures):
    """Resonance curves with and without damping: each damped forced scene "<twin>-damped" (tag
    "damped") beside its undamped twin "<twin>", max |tau| / H against the forcing frequency, one
    colour per solver (damped solid, undamped dashed). The undamped curve has no finite value at a
    resonance (a gap); the damped one stays finite there."""
    by_name = {s[K.name]: s for s in figures.scenes}
    pairs = [(s, by_name.get(s[K.name][:-len("-damped")])) for s in figures.scenes
             if "damped" in s.get(K.tags, []) and s[K.name].endswith("-damped")]
    pairs = [(d, u) for d, u in pairs if u is not None]
    for damped, twin in pairs:
        fig, ax = plt.subplots(figsize=(7.5, 4.6))
        drawn = False
        for scene, style, label in ((twin, "--", "undamped"), (damped, "-", "damped")):
            h = scene.get(K.statics, {}).get(K.horizontal_force_n, 1.0) or 1.0
            for solver, out in scene[K.solvers].items():
                points = [(r[K.omega_rad_s], r[K.max_abs_tension_n] / h if not r.get(K.diagnostic) else math.nan)
                          for r in out.get(K.forced, [])]
                if not points or solver not in STYLE:
                    continue
                _, marker, color = STYLE[solver]
                ax.plot(*zip(*points), linestyle=style, marker=marker, markersize=3, color=color,
                        label=f"{solver}, {label}")
                drawn = True
        if not drawn:
            plt.close(fig)
            continue
        ax.set_yscale("log")
        ax.set_xlabel("forcing frequency [rad/s]")
        ax.set_ylabel("max |tau| / H (modulus)")
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
        figures.save(fig, f"resonance-{damped[K.name]}.png",
                     f"Resonance curves with and without damping: {damped[K.name]} (solid) against its undamped "
                     f"twin {twin[K.name]} (dashed). Undamped, the response has no finite value at a natural "
                     "frequency (gaps); damped, the peak is finite, of height ~ 1 / (2 zeta).")


def pareto(figures, csv_path):
    """Time against error per scene from benchmarks/results/time-vs-error.csv (issue 8)."""
    path = pathlib.Path(csv_path)
    if not path.exists():
        return
    rows = read_table(path)
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    fig, axes = plt.subplots(1, len(scenes), figsize=(4.2 * len(scenes), 4), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for solver in STYLE:
            pts = sorted((float(r["time_s"]) * 1e3, float(r["max_rel_error"])) for r in rows
                         if r["scene"] == scene and r["solver"] == solver and r["max_rel_error"] not in ("nan", "")
                         and float(r["max_rel_error"]) > 0)
            if pts:
                _, marker, color = STYLE[solver]
                ax.plot(*zip(*pts), linestyle="none", marker=marker, color=color, label=solver)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(scene, fontsize=8)
        ax.set_xlabel("wall time [ms]")
        ax.grid(alpha=0.3)
        for target in (1e-3, 1e-6, 1e-9):
            ax.axhline(target, color="0.8", linewidth=0.7)
        ax.legend(fontsize=7)
    axes[0][0].set_ylabel("max relative error, first 6 in-plane frequencies")
    figures.save(fig, "time-vs-error.png",
                 "Time against error (benchmarks/results/time-vs-error.csv, 2-core machine): each solver's "
                 "resolution knob swept (fe: N with and without Richardson; shooting: rtol; frobenius: "
                 "tolerance), error against shooting at rtol 1e-13.")


def validity_maps(figures, validity_dir):
    """The validity maps (validity_maps.py, next to this script) of the sweeps found in validity_dir."""
    sys.path.insert(0, str(DATA_DIR))
    import validity_maps as maps  # noqa: PLC0415

    drawn, notes = maps.draw_all(validity_dir, figures.out)
    for name, caption in drawn:
        figures.index.append({K.file: name, K.caption: caption})
    for note in notes:
        print(note)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", required=True)
    parser.add_argument("--published", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--time-vs-error", default=str(DATA_DIR / "benchmarks" / "time-vs-error.csv"))
    parser.add_argument("--validity", help="sweep outputs <geometry>/points.csv of the validity maps "
                        "(default: validity/ next to --out, i.e. the report's DIR/validity)")
    args = parser.parse_args()
    with open(args.results) as f:
        results = json.load(f)
    pathlib.Path(args.out).mkdir(parents=True, exist_ok=True)
    figures = Figures(results, args.published, args.out)
    for draw in (figures.grinfogel, figures.mode_shapes, figures.dynamic_tension, figures.gale_frequencies,
                 figures.gale_forced, figures.model_error):
        draw()
    damped_resonance(figures)
    pareto(figures, args.time_vs_error)
    validity_maps(figures, args.validity or pathlib.Path(args.out).parent / "validity")
    with open(pathlib.Path(args.out) / "index.json", "w") as f:
        json.dump(figures.index, f, indent=1)
    print(f"drew {len(figures.index)} figures in {args.out}")


if __name__ == "__main__":
    main()
