# SPDX-License-Identifier: MIT
"""The columns of a sweep's points.csv and the solve of a batch of points, on a Dask worker.

Each point is `catena.solve` of the base scene with the point's values set (the same dict, so the
same TOML text, the same reader and the same doubles as a user's own call), without the
cross-checks, which change no number. Floats are written with repr, which round-trips: the CSV holds
the very doubles (read it with pandas' float_precision="round_trip"). A missing value is an empty
cell. The column list is a contract (docs/how-to/sweep.md).
"""

import csv
import io
import math
import time
from typing import Any, Optional

from ._sweep_spec import Axis, Outputs, scene_with

PLANES = ("inplane", "outofplane")
STATICS_FIELDS = ("horizontal_force_n", "vertical_force_a_n", "vertical_force_b_n", "tension_a_n",
                  "tension_b_n", "stretched_length_m", "converged")
#: The exact solvers, most trusted first on ties: a difference is taken against the one of these with
#: the smallest error estimate at that point. The analytic models (asymptotic, airy) are never a
#: reference: their error is what the differences measure.
EXACT_SOLVERS = ("shooting", "frobenius", "fe")


def group_fields() -> list[str]:
    """The fields of catena.dimensionless_groups() (catena.Groups' properties), sorted by name."""
    from ._catena import Groups

    return sorted(n for n in dir(Groups) if not n.startswith("_") and isinstance(getattr(Groups, n), property))


def _mode_columns(outputs: Outputs) -> list[tuple[str, int]]:
    planes = {"inplane": outputs.inplane_modes, "outofplane": outputs.outofplane_modes}
    return [(plane, k) for plane in PLANES for k in range(1, planes[plane] + 1)]


def columns(axes: list[Axis], outputs: Outputs) -> list[str]:
    names = ["point"] + [axis.key for axis in axes]
    for solver in outputs.solvers:
        names.append(f"{solver}.status")
        for plane, k in _mode_columns(outputs):
            names.append(f"{solver}.{plane}.mode{k}.omega_rad_s")
            if outputs.error_estimates:
                names.append(f"{solver}.{plane}.mode{k}.relative_error_estimate")
            if outputs.differences != "none":
                names.append(f"{solver}.{plane}.mode{k}.relative_difference")
    if outputs.differences != "none":
        names += [f"reference.{plane}" for plane in PLANES if _plane_kept(outputs, plane)]
    if outputs.statics:
        names += [f"statics.{name}" for name in STATICS_FIELDS]
    if outputs.groups:
        names += [f"groups.{name}" for name in group_fields()]
    return names + ["error", "wall_time_s"]


def _plane_kept(outputs: Outputs, plane: str) -> bool:
    return (outputs.inplane_modes if plane == "inplane" else outputs.outofplane_modes) > 0


def _cell(value: Any) -> str:
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) or hasattr(value, "dtype"):
        value = float(value)
        return "" if math.isnan(value) else repr(value)
    return str(value).replace("\r", " ").replace("\n", " / ")  # one physical line per row


def _mode_value(array: Any, k: int) -> Optional[float]:
    return float(array[k - 1]) if array is not None and len(array) >= k else None


def _plane_modes(result: Any, solver: str, plane: str) -> Any:
    if result is None or solver not in result:
        return None
    return getattr(result[solver], plane)


def _reference(result: Any, plane: str, count: int) -> Optional[str]:
    """The exact solver with the smallest largest error estimate over the kept modes of `plane`,
    among those that ran usably and gave all of them; None if none did."""
    best, best_error = None, math.inf
    for solver in EXACT_SOLVERS:
        modes = _plane_modes(result, solver, plane)
        if modes is None or not result[solver].summary.usable or len(modes.omega_rad_s) < count:
            continue
        estimates = [float(e) for e in modes.relative_error_estimate[:count]]
        worst = max((math.inf if math.isnan(e) else e) for e in estimates) if estimates else 0.0
        if best is None or worst < best_error:
            best, best_error = solver, worst
    return best


def _row(point: int, values: list[Any], result: Any, error: Optional[str], wall: float,
         outputs: Outputs) -> list[Any]:
    row: list[Any] = [point] + list(values)
    kept = {plane: (outputs.inplane_modes if plane == "inplane" else outputs.outofplane_modes) for plane in PLANES}
    references = {p: _reference(result, p, kept[p]) for p in PLANES} if outputs.differences != "none" else {}
    for solver in outputs.solvers:
        ran = result is not None and solver in result
        row.append(result[solver].summary.status if ran else ("error" if error else "not_run"))
        for plane, k in _mode_columns(outputs):
            modes = _plane_modes(result, solver, plane)
            omega = _mode_value(modes.omega_rad_s if modes is not None else None, k)
            row.append(omega)
            if outputs.error_estimates:
                row.append(_mode_value(modes.relative_error_estimate if modes is not None else None, k))
            if outputs.differences != "none":
                reference = references[plane]
                ref_modes = _plane_modes(result, reference, plane) if reference else None
                ref = _mode_value(ref_modes.omega_rad_s if ref_modes is not None else None, k)
                row.append(abs(omega - ref) / ref if omega is not None and ref else None)
    if outputs.differences != "none":
        row += [references[plane] for plane in PLANES if kept[plane] > 0]
    statics = result.statics if result is not None else None
    if outputs.statics:
        row += [getattr(statics, name) if statics is not None else None for name in STATICS_FIELDS]
    if outputs.groups:
        groups = result.groups if result is not None else None
        row += [getattr(groups, name) if groups is not None else None for name in group_fields()]
    return row + [error or (result.error if result is not None else None), wall]


def solve_point(scene: dict[str, Any], axes: list[Axis], values: list[Any], outputs: Outputs) -> tuple[Any, Optional[str], float]:
    """catena.solve of the point's scene: (result or None, the reader's refusal or None, wall time [s])."""
    from . import InvalidInput, solve

    start = time.perf_counter()
    try:
        result, error = solve(scene_with(scene, axes, values), solvers=outputs.solvers, checks=False), None
    except InvalidInput as refusal:  # a combination of values the scene refuses (extremes were probed)
        result, error = None, f"the scene is refused: {refusal}"
    return result, error, time.perf_counter() - start


def solve_batch(scene: dict[str, Any], axes: list[Axis], points: list[tuple[int, list[Any]]],
                outputs: Outputs) -> tuple[str, float]:
    """Solves the points (index, values) of one task: their CSV rows as text (one line each, in the
    given order) and the sum of their solve times [s]."""
    text = io.StringIO()
    writer = csv.writer(text, lineterminator="\n")
    busy = 0.0
    for point, values in points:
        result, error, wall = solve_point(scene, axes, values, outputs)
        busy += wall
        writer.writerow([_cell(v) for v in _row(point, values, result, error, wall, outputs)])
    return text.getvalue(), busy
