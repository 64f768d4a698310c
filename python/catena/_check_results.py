# SPDX-License-Identifier: MIT
"""Another code's results given in memory to catena.check, written as the JSON text of
`catena check`'s .json format (docs/how-to/check.md) and read by the library's one reader, so that rows
and columns are checked exactly like a file, with the same messages ("<results>" where a file name
would be, "results[i]" the 0-based row).

Accepted: a list of rows (dicts with "plane", "mode", "frequency_hz" or "omega_rad_s", optionally
"resolution" and "shape"); a dict {"results": rows}; or a dict of columns of equal length (lists or
numpy arrays) with the same names, where None in a column means the row does not give that field.
"""

import json
import math
import numbers
from collections.abc import Mapping, Sequence
from typing import Any

ORIGIN = "<results>"


class _NotAValue(Exception):
    pass


def _plain(value: Any, path: str) -> Any:
    """`value` as plain JSON data. A non-finite number becomes its text, so that the reader says
    which field is not a number (JSON itself has no NaN)."""
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        value = float(value)
        return value if math.isfinite(value) else repr(value)
    if hasattr(value, "tolist") and callable(value.tolist):  # numpy arrays and scalars
        return _plain(value.tolist(), path)
    if isinstance(value, Mapping):
        return {str(k): _plain(v, f"{path}.{k}") for k, v in value.items()}
    if isinstance(value, Sequence):
        return [_plain(v, f"{path}[{i}]") for i, v in enumerate(value)]
    raise _NotAValue(f"{ORIGIN}: {path}: a {type(value).__name__} is not a results value")


def _column_values(columns: Mapping[str, Any]) -> dict[str, list[Any]]:
    lengths = {}
    for name, column in columns.items():
        if isinstance(column, (str, bytes)) or not (isinstance(column, Sequence) or hasattr(column, "tolist")):
            raise _NotAValue(f"{ORIGIN}: column '{name}': a {type(column).__name__} is not a column "
                             "(a list or a 1-D array)")
        values = column.tolist() if hasattr(column, "tolist") else list(column)
        if not isinstance(values, list) or any(isinstance(v, list) for v in values):
            raise _NotAValue(f"{ORIGIN}: column '{name}': not one-dimensional")
        lengths[name] = values
    sizes = {name: len(values) for name, values in lengths.items()}
    if len(set(sizes.values())) > 1:
        raise _NotAValue(f"{ORIGIN}: columns of different lengths: {sizes}")
    return lengths


def _rows_of_columns(columns: Mapping[str, Any]) -> list[dict[str, Any]]:
    values = _column_values(columns)
    count = len(next(iter(values.values()))) if values else 0
    return [{name: column[i] for name, column in values.items() if column[i] is not None} for i in range(count)]


def results_json_text(results: Any) -> str:
    """The JSON text of `results` (rows, {"results": rows} or columns); raises _NotAValue with a
    message naming the row or column for values JSON cannot carry."""
    if isinstance(results, Mapping):
        document = dict(results) if "results" in results else {"results": _rows_of_columns(results)}
    elif isinstance(results, Sequence) and not isinstance(results, (str, bytes)):
        document = {"results": list(results)}
    else:
        raise TypeError(f"results: expected a path, a list of dicts or a dict of columns, got "
                        f"{type(results).__name__}")
    plain = {key: _plain(value, key) for key, value in document.items()}
    return json.dumps(plain, allow_nan=False)
