# SPDX-License-Identifier: MIT
"""The SPEC of a sweep (docs/how-to/sweep.md): read, validated before anything runs, and its points.

A SPEC names a base scene (a file relative to the SPEC, or an inline [scene] table), one [[axes]]
entry per swept scene key path, whether the axes form a grid or are zipped, and the [outputs] to
keep. Every error is a catena.InvalidInput naming the SPEC field (``axes[2].from``, ...).
Points are numbered 0.. in the spec's order: for a grid the LAST axis varies fastest.
"""

import copy
import difflib
import hashlib
import json
import math
import os
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, Optional

import numpy

from ._catena import InvalidInput

#: The keys of each table of a SPEC: anything else is refused (a typo must not silently pass).
_TOP_KEYS = {"scene", "axes", "zip", "outputs"}
_AXIS_KEYS = {"key", "values", "from", "to", "points", "spacing", "samples", "sampling", "seed"}
_OUTPUT_KEYS = {"solvers", "modes", "error_estimates", "statics", "groups", "differences"}
_DIFFERENCES = ("none", "most_accurate")


@dataclass
class Axis:
    key: str
    path: list[Any]  # the key path's parts: table names and 0-based array indices
    values: list[Any]  # the axis's values, in order (floats, or the given values as given)


@dataclass
class Outputs:
    solvers: list[str]
    inplane_modes: int
    outofplane_modes: int
    error_estimates: bool = True
    statics: bool = True
    groups: bool = True
    differences: str = "none"


@dataclass
class Spec:
    """A validated SPEC. `scene` is the base scene's TOML tree (a dict)."""
    scene: dict[str, Any]
    scene_origin: str
    axes: list[Axis]
    zip: bool
    outputs: Outputs
    text: dict[str, Any] = field(default_factory=dict)  # the SPEC as read (echoed in summary.json)

    @property
    def points(self) -> int:
        if self.zip:
            return len(self.axes[0].values)
        return math.prod(len(axis.values) for axis in self.axes)

    def point_values(self, point: int) -> list[Any]:
        """The axis values of point `point` (0-based), one per axis in the spec's order."""
        if self.zip:
            return [axis.values[point] for axis in self.axes]
        values = []
        for axis in reversed(self.axes):  # the last axis varies fastest
            point, index = divmod(point, len(axis.values))
            values.append(axis.values[index])
        return values[::-1]

    def scene_at(self, point: int) -> dict[str, Any]:
        """The base scene with point `point`'s values set: a new dict (the base is untouched)."""
        return scene_with(self.scene, self.axes, self.point_values(point))

    def digest(self) -> str:
        """A hash of everything that decides the numbers and columns (the scene's content, not its
        path): a journal written for another digest is not resumed."""
        canonical = {
            "scene": self.scene, "axes": [[a.key, a.values] for a in self.axes], "zip": self.zip,
            "outputs": self.outputs.__dict__,
        }
        text = json.dumps(canonical, sort_keys=True, default=repr)
        return hashlib.sha256(text.encode()).hexdigest()


def _python_value(value: Any) -> Any:
    """numpy scalars as Python ones (repr of a float round-trips; TOML needs plain values)."""
    if isinstance(value, numpy.generic):
        return value.item()
    return value


def parse_key_path(key: str, where: str) -> list[Any]:
    """"line.segments.1.EA" -> ["line", "segments", 0, "EA"] (numbers are 1-based array indices)."""
    if not isinstance(key, str) or not key.strip():
        raise InvalidInput(f"{where}: a scene key path such as \"taut_inclined.eps\" or \"line.segments.1.EA\"")
    parts: list[Any] = []
    for part in key.split("."):
        if not part:
            raise InvalidInput(f"{where} = {key!r}: an empty part (two dots, or a dot at an end)")
        if part.isdigit():
            if int(part) < 1:
                raise InvalidInput(f"{where} = {key!r}: array indices are 1-based, got {part}")
            parts.append(int(part) - 1)
        else:
            parts.append(part)
    if isinstance(parts[0], int):
        raise InvalidInput(f"{where} = {key!r}: starts with an index; it starts with a table, e.g. \"cable\"")
    return parts


def missing_part(scene: Mapping[str, Any], path: list[Any]) -> Optional[str]:
    """None if every part of `path` but the last exists in `scene` (the last may be a key the scene
    leaves at its default); else which part is missing, with the keys close to it."""
    node: Any = scene
    for depth, part in enumerate(path):
        where = ".".join(str(p + 1) if isinstance(p, int) else p for p in path[:depth]) or "the scene"
        if isinstance(part, int):
            if not isinstance(node, list):
                return f"{where} is not an array of tables, so it has no index {part + 1}"
            if part >= len(node):
                return f"{where} has {len(node)} entries, so it has no index {part + 1}"
            node = node[part]
            continue
        if not isinstance(node, Mapping):
            return f"{where} is a value, not a table, so it has no key {part!r}"
        if part not in node:
            if depth == len(path) - 1:
                return None  # the reader decides whether the table knows this key
            close = difflib.get_close_matches(part, [str(k) for k in node], n=4, cutoff=0.5)
            hint = f" (close: {', '.join(close)})" if close else f" (it has: {', '.join(map(str, node))})"
            return f"{part!r} is not a key of {where}{hint}"
        node = node[part]
    if isinstance(node, (Mapping, list)) and not (isinstance(node, list) and node and not isinstance(node[0], Mapping)):
        return f"{'.'.join(str(p) for p in path)} is a table, not a value"
    return None


def scene_with(base: Mapping[str, Any], axes: list[Axis], values: list[Any]) -> dict[str, Any]:
    scene = copy.deepcopy(dict(base))
    for axis, value in zip(axes, values):
        if value is None:  # an axis left at the base scene's value (the probes)
            continue
        node: Any = scene
        for part in axis.path[:-1]:
            if isinstance(part, str) and part not in node:
                node[part] = {}
            node = node[part]
        node[axis.path[-1]] = _python_value(value)
    return scene


def _number(value: Any, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise InvalidInput(f"{where} = {value!r}: a finite number")
    return float(value)


def _count(value: Any, where: str, minimum: int = 1) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < minimum:
        raise InvalidInput(f"{where} = {value!r}: an integer >= {minimum}")
    return value


def _range_values(entry: Mapping[str, Any], where: str) -> list[float]:
    for name in ("from", "to", "points"):
        if name not in entry:
            raise InvalidInput(f"{where}.{name}: missing (a range gives from, to and points)")
    low, high = _number(entry["from"], f"{where}.from"), _number(entry["to"], f"{where}.to")
    points = _count(entry["points"], f"{where}.points")
    spacing = entry.get("spacing", "linear")
    if spacing == "linear":
        return [float(v) for v in numpy.linspace(low, high, points)]
    if spacing == "log":
        for name, bound in (("from", low), ("to", high)):
            if bound <= 0:
                raise InvalidInput(f"{where}.{name} = {bound!r}: a log spacing needs bounds > 0")
        return [float(v) for v in numpy.geomspace(low, high, points)]
    raise InvalidInput(f"{where}.spacing = {spacing!r}: \"linear\" or \"log\"")


def _sampled_values(entry: Mapping[str, Any], where: str, axis_index: int) -> list[float]:
    """Random or Latin-hypercube samples of [from, to]: numpy's generator seeded by `seed` (and the
    axis index, so that two axes of one seed are independent)."""
    samples = _count(entry["samples"], f"{where}.samples")
    for name in ("from", "to", "seed"):
        if name not in entry:
            raise InvalidInput(f"{where}.{name}: missing (samples are drawn in [from, to] from a seed)")
    low, high = _number(entry["from"], f"{where}.from"), _number(entry["to"], f"{where}.to")
    seed = _count(entry["seed"], f"{where}.seed", 0)
    rng = numpy.random.default_rng([seed, axis_index])
    sampling = entry.get("sampling", "random")
    if sampling == "random":
        unit = rng.random(samples)
    elif sampling == "latin_hypercube":
        unit = (rng.permutation(samples) + rng.random(samples)) / samples  # one sample per stratum
    else:
        raise InvalidInput(f"{where}.sampling = {sampling!r}: \"random\" or \"latin_hypercube\"")
    return [float(v) for v in low + (high - low) * unit]


def _axis(entry: Any, index: int) -> Axis:
    where = f"axes[{index}]"
    if not isinstance(entry, Mapping):
        raise InvalidInput(f"{where}: a table ([[axes]] with key and values)")
    unknown = sorted(set(entry) - _AXIS_KEYS)
    if unknown:
        raise InvalidInput(f"{where}.{unknown[0]}: unknown key; known here: {', '.join(sorted(_AXIS_KEYS))}")
    if "key" not in entry:
        raise InvalidInput(f"{where}.key: missing (the scene key path to sweep, e.g. \"taut_inclined.eps\")")
    path = parse_key_path(entry["key"], f"{where}.key")
    kinds = [k for k in ("values", "points", "samples") if k in entry]
    if len(kinds) != 1:
        raise InvalidInput(f"{where}: give exactly one of values = [...], from/to/points, or samples "
                           f"(got {', '.join(kinds) if kinds else 'none'})")
    if kinds[0] == "values":
        values = entry["values"]
        if not isinstance(values, list):
            raise InvalidInput(f"{where}.values: an array, e.g. [1.0, 2.0]")
        for i, value in enumerate(values):
            if isinstance(value, (list, dict)):
                raise InvalidInput(f"{where}.values[{i}]: a single value (number, string or bool)")
    elif kinds[0] == "points":
        values = _range_values(entry, where)
    else:
        values = _sampled_values(entry, where, index)
    if not values:
        raise InvalidInput(f"{where}.values: empty (an axis needs at least one value)")
    return Axis(entry["key"], path, list(values))


def _flag(table: Mapping[str, Any], name: str, default: bool) -> bool:
    value = table.get(name, default)
    if not isinstance(value, bool):
        raise InvalidInput(f"outputs.{name} = {value!r}: true or false")
    return value


def _outputs(table: Any, scene_solvers: list[str], request: Mapping[str, Any]) -> Outputs:
    from . import solvers as registry  # the registry's names, not a list of our own

    if not isinstance(table, Mapping):
        raise InvalidInput("outputs: a table")
    unknown = sorted(set(table) - _OUTPUT_KEYS)
    if unknown:
        raise InvalidInput(f"outputs.{unknown[0]}: unknown key; known here: {', '.join(sorted(_OUTPUT_KEYS))}")
    known = [s.name for s in registry()]
    names = table.get("solvers", scene_solvers)
    if isinstance(names, str) or not isinstance(names, list) or not names:
        raise InvalidInput(f"outputs.solvers = {names!r}: a non-empty array of solver names ({', '.join(known)})")
    for i, name in enumerate(names):
        if name not in known:
            close = difflib.get_close_matches(str(name), known, n=2)
            raise InvalidInput(f"outputs.solvers[{i}] = {name!r}: not a solver"
                               f"{' (close: ' + ', '.join(close) + ')' if close else ''}; solvers: {', '.join(known)}")
    planes = {"inplane": int(request.get("inplane_modes", 6)), "outofplane": int(request.get("outofplane_modes", 0))}
    kept = dict(planes)
    if "modes" in table:
        modes = _count(table["modes"], "outputs.modes", 0)
        for plane, asked in planes.items():
            if asked and modes > asked:
                raise InvalidInput(f"outputs.modes = {modes}: more than the scene's request.{plane}_modes = "
                                   f"{asked}; raise it in the scene")
            kept[plane] = min(modes, asked)
    differences = table.get("differences", "none")
    if differences not in _DIFFERENCES:
        raise InvalidInput(f"outputs.differences = {differences!r}: one of {', '.join(map(repr, _DIFFERENCES))}")
    return Outputs(list(names), kept["inplane"], kept["outofplane"], _flag(table, "error_estimates", True),
                   _flag(table, "statics", True), _flag(table, "groups", True), differences)


def _base_scene(text: Mapping[str, Any], base_dir: str) -> tuple[dict[str, Any], str]:
    if "scene" not in text:
        raise InvalidInput("scene: missing (scene = \"base.toml\", relative to the SPEC, or an inline [scene] table)")
    scene = text["scene"]
    if isinstance(scene, str):
        path = os.path.join(base_dir, scene)
        try:
            with open(path, "rb") as file:
                tree = tomllib.load(file)
        except FileNotFoundError:
            raise InvalidInput(f"scene = {scene!r}: file not found ({path})") from None
        except tomllib.TOMLDecodeError as error:
            raise InvalidInput(f"scene = {scene!r}: not TOML: {error}") from None
        return tree, path
    if isinstance(scene, Mapping):
        return copy.deepcopy(dict(scene)), "[scene]"
    raise InvalidInput("scene: a file name (string) or an inline [scene] table")


def read_spec(source: Any) -> Spec:
    """A Spec from a SPEC file path or a dict with the file's structure; InvalidInput naming the field.
    The scene is read by Catena's reader at each axis's extremes (the others at their first value)."""
    if isinstance(source, Spec):
        return source
    if isinstance(source, (str, os.PathLike)):
        try:
            with open(source, "rb") as file:
                text = tomllib.load(file)
        except FileNotFoundError:
            raise InvalidInput(f"SPEC {os.fspath(source)}: file not found") from None
        except tomllib.TOMLDecodeError as error:
            raise InvalidInput(f"SPEC {os.fspath(source)}: not TOML: {error}") from None
        base_dir = os.path.dirname(os.path.abspath(source))
    elif isinstance(source, Mapping):
        text, base_dir = dict(source), os.getcwd()
    else:
        raise TypeError(f"spec: expected a SPEC file path or a dict, got {type(source).__name__}")
    unknown = sorted(set(text) - _TOP_KEYS)
    if unknown:
        raise InvalidInput(f"{unknown[0]}: unknown SPEC key; known: {', '.join(sorted(_TOP_KEYS))}")
    scene, origin = _base_scene(text, base_dir)
    if "sweep" in scene:
        raise InvalidInput(f"scene ({origin}): has a [sweep] table; a SPEC's [[axes]] replace it: remove it")
    entries = text.get("axes")
    if not isinstance(entries, list) or not entries:
        raise InvalidInput("axes: missing or empty (one [[axes]] table per swept key)")
    axes = [_axis(entry, i) for i, entry in enumerate(entries)]
    zipped = text.get("zip", False)
    if not isinstance(zipped, bool):
        raise InvalidInput(f"zip = {zipped!r}: true or false")
    if zipped and len({len(a.values) for a in axes}) > 1:
        lengths = ", ".join(f"axes[{i}] {len(a.values)}" for i, a in enumerate(axes))
        raise InvalidInput(f"zip = true: the axes must have equal lengths ({lengths})")
    keys = [a.key for a in axes]
    for i, key in enumerate(keys):
        if keys.index(key) != i:
            raise InvalidInput(f"axes[{i}].key = {key!r}: also axes[{keys.index(key)}].key")
    request = scene.get("request", {}) if isinstance(scene.get("request", {}), Mapping) else {}
    scene_solvers = list(scene["solvers"]) if isinstance(scene.get("solvers"), Mapping) else None
    probe = _probe_scene(scene, origin, axes)
    spec = Spec(scene, origin, axes, zipped,
                _outputs(text.get("outputs", {}), scene_solvers or probe.solver_names(), request), text)
    return spec


def _probe_scene(scene: dict[str, Any], origin: str, axes: list[Axis]) -> Any:
    """Reads the scene with each axis at its first and last value (the others at their first): a key
    the scene does not know, or a value it refuses, is an error before anything runs."""
    from . import load_scenes

    for i, axis in enumerate(axes):
        missing = missing_part(scene, axis.path)
        if missing:
            raise InvalidInput(f"axes[{i}].key = {axis.key!r}: {missing}")
    def read(values: list[Any], where: str) -> Any:
        try:
            return load_scenes(scene_with(scene, axes, values))[0]
        except InvalidInput as error:
            raise InvalidInput(f"{where}: the scene ({origin}) is refused: {error}") from None

    first = read([], "scene")  # the base scene as given (scene_with sets no axis for no values)
    for i, axis in enumerate(axes):
        for label, value in (("first", axis.values[0]), ("last", axis.values[-1])):
            read([None] * i + [value], f"axes[{i}] (key {axis.key!r}) at its {label} value {value!r}")
    read([a.values[0] for a in axes], "the point 0 (every axis at its first value)")
    return first
