# SPDX-License-Identifier: MIT
"""Catena: linear dynamics of cables by five independent solvers, from Python.

The library itself (not a wrapper around the command line): scenes from TOML files or dicts,
statics, each solver on its own with its knobs, results as numpy arrays. Units are SI and carried
in every name. Documentation: docs/reference/python.md.

    >>> import catena
    >>> r = catena.solve("verification/scenes/physical/mooring-line-900m.toml")
    >>> r.statics.horizontal_force_n
    >>> r["shooting"].inplane.omega_rad_s          # numpy array, lowest first
    >>> r["shooting"].inplane.eigenvalue           # complex roots -delta + i omega_d (damping)

Each solver also runs on its own: catena.solve_fe(problem, request, elements=800), and likewise
solve_shooting, solve_frobenius, solve_asymptotic, solve_airy, with their knobs as typed keyword
arguments. A missing value (no error estimate, not asked, not counted) is None, or NaN in an array.

catena.sweep(spec) solves a scene over a grid or a sample of its values on Dask and returns a pandas
DataFrame (docs/how-to/sweep.md); `python3 -m catena sweep` is its command line.

Errors: bad input raises catena.InvalidInput (a ValueError) naming the field; an unreadable or
malformed scene raises catena.ParseError (a subclass of InvalidInput). Numerical trouble is never
an exception: it is a status in each result's summary. Solves release the GIL.
"""

import importlib
import json
import os
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Optional, Union

from ._catena import (Cable, CertifiedReference, Check, ConvergenceStudy, dimensionless_groups,
                      DynamicTension, DynamicTensionEnd, Environment, ExternalCheck, ForcedRequest,
                      ForcedResponse, Groups, InvalidInput, Line, LineSegment, Mode, ModeComparison,
                      Modes, ModeShapes, MotionRequest, ParseError, PointAttachment, Problem, Request,
                      ResolutionComparison, Result, run_solver, Scene, Seabed, solve_statics, SolverResult,
                      Statics, Summary, TensionCheck, TimeSeriesCheck, TimeSeriesMode, __version__)
from . import _catena
from . import _plot
from ._check_results import ORIGIN as _RESULTS_ORIGIN, _NotAValue, results_json_text
from ._scene_dict import scene_toml_text
from ._solver_functions import solve_airy, solve_asymptotic, solve_fe, solve_frobenius, solve_shooting
from ._sweep_run import sweep

__all__ = [
    "Cable", "CertifiedReference", "Check", "ConvergenceStudy", "DynamicTension", "DynamicTensionEnd",
    "Environment", "ExternalCheck", "ForcedRequest", "ForcedResponse", "Groups", "InvalidInput", "Knob",
    "Line", "LineSegment", "Mode", "ModeComparison", "Modes", "ModeShapes", "MotionRequest", "ParseError",
    "PointAttachment", "Problem", "Seabed", "Request", "ResolutionComparison", "Result", "Scene",
    "SolverInfo", "SolverResult", "Statics", "Summary", "TensionCheck", "TimeSeriesCheck", "TimeSeriesMode",
    "check", "check_tension", "check_timeseries",
    "dimensionless_groups", "load_scene", "load_scenes", "run_solver", "solve", "solve_airy",
    "solve_asymptotic", "solve_fe", "solve_frobenius", "solve_shooting", "solve_statics", "solve_sweep",
    "solvers", "sweep", "__version__",
]

#: What names a scene: the path of a TOML file, a dict with the file's structure, or a Scene.
SceneSource = Union[str, os.PathLike[str], Mapping[str, Any], Scene]
#: Solver names: one, several, or None for the scene's own list.
SolverNames = Union[str, Iterable[str], None]


def load_scenes(scene: SceneSource) -> list[Scene]:
    """The scenes of a TOML file (path) or of a dict with the file's structure: one, or one per
    value of a [sweep]. A dict goes through the same reader as a file (docs/reference/python.md)."""
    if isinstance(scene, Scene):
        return [scene]
    if isinstance(scene, Mapping):
        return _catena._parse_scene_text(scene_toml_text(scene), "<dict>")
    if isinstance(scene, (str, os.PathLike)):
        if not os.path.exists(scene):
            raise FileNotFoundError(2, "scene file not found", os.fspath(scene))
        return _catena._read_scene_file(os.fspath(scene))
    raise TypeError(f"scene: expected a path, a dict or a catena.Scene, got {type(scene).__name__}")


def load_scene(scene: SceneSource) -> Scene:
    """One scene (path, dict or Scene); a sweep raises InvalidInput (use load_scenes)."""
    scenes = load_scenes(scene)
    if len(scenes) != 1:
        raise InvalidInput(f"{scenes[0].file}: [sweep] gives {len(scenes)} scenes: use catena.load_scenes "
                           "or catena.solve_sweep")
    return scenes[0]


def _solver_list(solvers: SolverNames) -> list[str]:
    if solvers is None:
        return []
    if isinstance(solvers, str):
        return [solvers]
    return list(solvers)


def solve(scene: SceneSource, *, solvers: SolverNames = None, time_limit_s: Optional[float] = None,
          checks: bool = True) -> Result:
    """Solves one scene as `catena solve` does: the statics once, then every applicable solver the
    scene names (all by default), then the cross-checks. Returns a Result.

    scene: path of a TOML scene file, a dict with the same structure (docs/reference/scene-format.md), or a
        Scene. A [sweep] raises InvalidInput (use solve_sweep).
    solvers: run only these solver names (default: the scene's [solvers], else all).
    time_limit_s: cooperative wall-clock budget of the scene [s]; solvers stop with what they have.
    checks: compute the cross-checks (result.checks) with the built-in tolerances.
    """
    return _catena._run_scene(load_scene(scene), _solver_list(solvers), time_limit_s, checks)


def solve_sweep(scene: SceneSource, *, solvers: SolverNames = None, time_limit_s: Optional[float] = None,
                checks: bool = True) -> list[Result]:
    """Solves every scene of a file or dict (each value of a [sweep]); a list of Result."""
    names = _solver_list(solvers)
    return [_catena._run_scene(s, names, time_limit_s, checks) for s in load_scenes(scene)]


def _existing_path(path: Union[str, os.PathLike[str]], what: str) -> str:
    if not os.path.exists(path):
        raise FileNotFoundError(2, f"{what} file not found", os.fspath(path))
    return os.fspath(path)


def check(results: Union[str, os.PathLike[str], Sequence[Mapping[str, Any]], Mapping[str, Any]],
          scene: SceneSource, rtol: float = 1e-3,
          shapes: Union[str, os.PathLike[str], None] = None) -> ExternalCheck:
    """Compares another code's natural frequencies with Catena's certified reference for `scene`, as
    `catena check` does (docs/how-to/check.md, docs/reference/python.md). Returns an ExternalCheck: `.references`
    (the solver used per plane and why), `.modes` (per mode of the other code: its value, Catena's
    value and estimate, the relative error, MAC, observed order, extrapolated limit, bias and the
    verdict), `.failed`, `.error` (no reference could be computed), `.to_json()`.

    results: the path of a CSV or .json results file (the CLI's formats); or a list of dicts
        {"plane", "mode", "frequency_hz" or "omega_rad_s", optional "resolution", optional "shape"};
        or {"results": that list}; or a dict of columns of equal length (lists or numpy arrays)
        with those names, None meaning a field the row does not give.
    scene: a path, a dict with the TOML's structure, or a Scene (as catena.solve).
    rtol: relative tolerance on frequencies, in (0, 1).
    shapes: the path of a long-format shapes CSV, with a CSV results file only (in-memory rows
        carry their own "shape": {"s_m", "u", "w", "v", "tension_n"}).

    Bad results raise InvalidInput naming the row and the field, with the CLI's messages. The
    reference solve releases the GIL.
    """
    scene = load_scene(scene)
    if isinstance(results, (str, os.PathLike)):
        shapes_path = "" if shapes is None else _existing_path(shapes, "shapes")
        return _catena._check_file(_existing_path(results, "results"), shapes_path, scene, rtol)
    if shapes is not None:
        raise InvalidInput("shapes: a shapes file goes with a CSV results file; rows given in Python carry "
                           "their own 'shape' ({'s_m': [...], 'u': [...], ...})")
    try:
        text = results_json_text(results)
    except _NotAValue as error:
        raise InvalidInput(str(error)) from None
    return _catena._check_json(text, _RESULTS_ORIGIN, scene, rtol)


def check_tension(results: Union[str, os.PathLike[str], Mapping[str, Any]], scene: SceneSource,
                  rtol: float = 1e-3) -> TensionCheck:
    """Compares another code's dynamic tension along a line with Catena's for the scene's
    [request.motion], as `catena check` does for a tension file (docs/how-to/check-dynamic-tension.md).
    Returns a TensionCheck: `.verdict`, `.failed`, `.error` (Catena could not compute the
    reference: no solver computed the dynamic tension, or the statics failed), the finest
    stations' `.s_m`, `.other_n`, `.catena_n`, `.difference_n`, `.allowed_n`, `.fairlead`,
    `.studies` (observed order, limit, bias), `.to_json()`.

    results: the path of a CSV file (the CLI's format); or a dict of columns of equal length (lists
        or numpy arrays) with the CSV's names ("s_m" or "node" and "nodes", "tension_std_n" or
        "tension_amplitude_n", optional "period_s", "resolution", "tension_uncertainty_n"), None
        meaning an empty cell.
    scene: a path, a dict with the TOML's structure, or a Scene (as catena.solve).
    rtol: relative agreement asked beyond both uncertainties, in (0, 1).

    Bad input raises InvalidInput naming the row and the column, with the CLI's messages.
    """
    scene = load_scene(scene)
    if isinstance(results, (str, os.PathLike)):
        return _catena._check_tension_file(_existing_path(results, "results"), scene, rtol)
    if not isinstance(results, Mapping):
        raise InvalidInput("results: a CSV path or a dict of columns")
    return _catena._check_tension_columns(dict(results), scene, rtol)


_TIME_KEYS = ("time", "time_s")


def check_timeseries(series: Union[str, os.PathLike[str], Sequence[Union[str, os.PathLike[str]]], Mapping[str, Any]],
                     scene: SceneSource, channels: Union[str, Sequence[str], None] = None, *,
                     time_s: Any = None, window: Optional[tuple[Optional[float], Optional[float]]] = None,
                     plane: Optional[str] = None, resolutions: Optional[Sequence[float]] = None,
                     min_frequency_hz: float = 0.0, max_frequency_hz: float = 0.0) -> TimeSeriesCheck:
    """Checks a free decay computed by another code against Catena's damped modes of `scene`, as
    `catena check FILE --channel NAME` does (docs/how-to/check-time-series.md). The modes in the
    channels are identified (matrix pencil + least squares, each with an uncertainty from the data)
    and matched to Catena's; each gets a verdict: "agrees", "disagrees", "not identifiable" or
    "unmatched". Returns a TimeSeriesCheck: `.modes` (TimeSeriesMode: identified f and zeta with
    their uncertainties, Catena's, the errors, the verdict, `.study` with several runs),
    `.not_present`, `.notes`, `.failed`, `.error`, `.to_json()`.

    series: a MoorDyn output file or a CSV with a time column (told by content); a list of them (runs
        at different resolutions, e.g. MoorDyn NumSegs, with `resolutions` or MoorDyn line files);
        or a dict {channel name: samples} with the times in `time_s` or in a "time" / "time_s" key.
    scene: a path, a dict with the TOML's structure, or a Scene (as catena.solve).
    channels: the channel name(s) to identify; default for a dict: every channel.
    window: (t0, t1) [s], the free decay after the release; None (or a None side): the record's
        start or end. It must span two periods of Catena's lowest mode.
    plane: "in-plane" or "out-of-plane" for every channel, when the names do not tell.

    Bad input raises InvalidInput (a ValueError) with the CLI's message; the work releases the GIL.
    """
    scene = load_scene(scene)
    start, end = (None, None) if window is None else window
    if isinstance(channels, str):
        channels = [channels]
    if isinstance(series, Mapping):
        columns = dict(series)
        keys = [k for k in columns if str(k).lower() in _TIME_KEYS]
        if time_s is None and not keys:
            raise InvalidInput("time_s: give the sample times [s] (time_s=..., or a 'time' key in the dict)")
        if time_s is not None and keys:
            raise InvalidInput(f"time_s: given twice (time_s=... and the key '{keys[0]}')")
        if keys:
            time_s = columns.pop(keys[0])
        names = [str(k) for k in columns]
        return _catena._check_timeseries_samples(
            time_s, names, [columns[k] for k in columns], scene, list(channels if channels is not None else names),
            start, end, plane or "", min_frequency_hz, max_frequency_hz)
    if time_s is not None:
        raise InvalidInput("time_s: the times of a file are in the file; time_s goes with a dict of samples")
    files = [series] if isinstance(series, (str, os.PathLike)) else list(series)
    if channels is None:
        raise InvalidInput("channels: which channel(s) of the file to identify (e.g. 'FAIRTEN1')")
    return _catena._check_timeseries_files([_existing_path(f, "time series") for f in files], scene,
                                           list(channels), start, end, plane or "",
                                           list(resolutions or []), min_frequency_hz, max_frequency_hz)


def _plot_result(self: Result, ax: Any = None, modes: Union[Iterable[int], str, None] = (1, 2, 3),
                 plane: str = "in-plane", mode_scale: float = 0.08) -> Any:
    """Draws the result on a matplotlib axes, as `catena plot` draws its panels (docs/how-to/plot.md);
    returns the axes.

    plane: "in-plane" (the static profile to scale, one line per segment, the ends, points, the seabed
        and touchdown points, with the in-plane modes as the displaced profile), "out-of-plane"
        (v(s) of the out-of-plane modes) or "tension" (the static tension T(s) [kN]).
    modes: mode numbers drawn (1-based), "all", or None/() for none. The modes are those of the most
        accurate exact solver that gave shapes (the axes' title names it in `catena plot`).
    ax: the axes to draw on (default: a new figure's).
    mode_scale: the largest in-plane displacement drawn, as a fraction of the profile's extent.

    The result must hold the static profile and the shapes: solve a scene whose [request] has
    shapes = true (InvalidInput otherwise, saying so).
    """
    if isinstance(modes, str):
        if modes != "all":
            raise InvalidInput(f"modes: {modes!r}: give mode numbers, 'all' or None")
        numbers, every = [], True
    else:
        numbers, every = [int(m) for m in (modes or ())], False
    picture = json.loads(_catena._scene_picture(self.to_json(), numbers, every, float(mode_scale)))
    try:
        panel = _plot.panel_of(picture, plane)
    except ValueError as error:
        raise InvalidInput(str(error)) from None
    if ax is None:
        plt: Any = importlib.import_module("matplotlib.pyplot")  # optional, untyped: by name
        _, ax = plt.subplots(figsize=(10, 4))
    _plot.draw_panel(ax, panel)
    return ax


Result.plot = _plot_result  # type: ignore[assignment]


@dataclass(frozen=True)
class Knob:
    """One knob of a solver (catena::KnobSpec)."""
    name: str
    description: str
    #: "integer", "real", "flag" or "choice"
    type: str
    #: the default as a Python value (int, float, bool or str)
    default: Union[int, float, bool, str]
    #: the default as a scene writes it
    default_text: str
    #: the valid values in words, e.g. "[2, 5e+07]", "(0, 0.01]", '"rk" or "adams" or "bdf"'
    valid: str


@dataclass(frozen=True)
class SolverInfo:
    """A solver of the registry: name, method and knobs."""
    name: str
    description: str
    knobs: tuple[Knob, ...]

    def defaults(self) -> dict[str, Union[int, float, bool, str]]:
        """{knob: default} as a Python dict."""
        return {knob.name: knob.default for knob in self.knobs}


def _default_value(kind: str, text: str) -> Union[int, float, bool, str]:
    if kind == "flag":
        return text == "true"
    if kind == "integer":
        return int(float(text)) if any(c in text for c in ".eE") else int(text)
    if kind == "real":
        return float(text)
    if text.startswith('"'):
        return str(json.loads(text))
    return text


def solvers() -> list[SolverInfo]:
    """Every solver, in registry order (fe, shooting, frobenius, asymptotic, airy), with its knobs:
    a list of SolverInfo. The same tables as `catena solvers` and docs/reference/solver-knobs.md."""
    return [
        SolverInfo(name, description,
                   tuple(Knob(k, d, kind, _default_value(kind, text), text, valid)
                         for k, d, kind, text, valid in knobs))
        for name, description, knobs in _catena._registry()
    ]
