# SPDX-License-Identifier: MIT
"""A scene given as a Python dict, written as TOML text for the one scene reader.

Dict scenes and file scenes go through the same strict reader (src/io/scene_reader.cpp): this
module only spells the dict in TOML, so every check, default and error message (naming
``[table].key``) is the reader's. Each top-level table becomes an inline table; floats are written
with ``repr``, which round-trips exactly, so a dict holding a file's values gives the same doubles.
Values that TOML cannot hold (None, objects, integers beyond 64 bits, cyclic or over-deep nesting)
raise catena.ParseError naming the key path.
"""

import json
import math
import numbers
from collections.abc import Mapping
from typing import Any

import numpy

from ._catena import ParseError

#: The reader accepts at most this nesting of arrays and inline tables (docs/reference/scene-format.md).
MAX_NESTING = 64
_INT64 = (-(2**63), 2**63 - 1)


def _where(path: tuple[Any, ...]) -> str:
    return "<dict>" + "".join(f"[{key!r}]" for key in path)


def _key(key: object, path: tuple[Any, ...]) -> str:
    if not isinstance(key, str):
        raise ParseError(f"{_where(path)}: keys must be strings, got {type(key).__name__} {key!r}")
    return json.dumps(key)


def _number(value: numbers.Real, path: tuple[Any, ...]) -> str:
    if isinstance(value, numbers.Integral):
        integer = int(value)
        if not _INT64[0] <= integer <= _INT64[1]:
            raise ParseError(f"{_where(path)} = {integer}: out of the range of a 64-bit integer")
        return str(integer)
    real = float(value)
    if math.isnan(real):
        return "nan"
    if math.isinf(real):
        return "inf" if real > 0 else "-inf"
    return repr(real)


def _value(value: Any, path: tuple[Any, ...], depth: int) -> str:
    if depth > MAX_NESTING:
        raise ParseError(f"{_where(path)}: nested deeper than {MAX_NESTING} levels (the limit)")
    if isinstance(value, (bool, numpy.bool_)):
        return "true" if value else "false"
    if isinstance(value, numbers.Real):
        return _number(value, path)
    if isinstance(value, str):
        return json.dumps(value)  # TOML basic strings share JSON's escapes
    if isinstance(value, Mapping):
        items = [f"{_key(k, path)} = {_value(v, path + (k,), depth + 1)}" for k, v in value.items()]
        return "{ " + ", ".join(items) + " }" if items else "{}"
    if isinstance(value, numpy.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        items = [_value(v, path + (i,), depth + 1) for i, v in enumerate(value)]
        return "[" + ", ".join(items) + "]"
    raise ParseError(
        f"{_where(path)}: a {type(value).__name__} is not a scene value "
        "(number, bool, string, list or dict)")


def scene_toml_text(scene: Mapping[str, Any]) -> str:
    """The TOML text of a scene dict (same structure as the file: docs/reference/scene-format.md)."""
    if not isinstance(scene, Mapping):
        raise TypeError(f"scene: expected a dict, got {type(scene).__name__}")
    lines = [f"{_key(k, ())} = {_value(v, (k,), 1)}" for k, v in scene.items()]
    return "\n".join(lines) + "\n"
