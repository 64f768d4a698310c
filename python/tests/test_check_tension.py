# SPDX-License-Identifier: MIT
"""catena.check_tension (docs/how-to/check-dynamic-tension.md, docs/reference/python.md): another
code's dynamic tension read from a CSV file or from columns given in Python, with the CLI's checks
and messages (the row and the column named), refused before any solve when the file or the scene
does not fit (the mooring scene has no [request.motion])."""

import math

import numpy
import pytest

import catena


def test_columns_beyond_the_line_name_the_row_and_column(mooring_path):
    # L = 1000 m: the second station is outside [0, L].
    with pytest.raises(catena.InvalidInput, match=r"<columns> row 2, column 's_m'"):
        catena.check_tension({"s_m": [0.0, 1000.5], "tension_std_n": [1.0, 2.0]}, mooring_path)


@pytest.mark.parametrize("columns, message", [
    ({"s_m": [0.0], "node": [0], "nodes": [3], "tension_std_n": [1.0]}, "columns 's_m' and 'node' both given"),
    ({"node": [0], "tension_std_n": [1.0]}, "column 'node' without column 'nodes'"),
    ({"s_m": numpy.array([0.0, 10.0]), "tension_std_n": numpy.array([1.0, math.nan])},
     r"row 2, column 'tension_std_n': 'nan' is not a finite number"),
    ({"s_m": [0.0, 10.0], "tension_std_n": [1.0, None]}, r"row 2, column 'tension_std_n': empty"),
    ({"s_m": [0.0, 10.0], "tension_std_n": [1.0]}, "column 'tension_std_n' has 1 values"),
    ({"s_m": [0.0], "tension": [1.0]}, "unknown column 'tension'"),
])
def test_bad_columns_raise_with_the_cli_messages(mooring_path, columns, message):
    with pytest.raises(catena.InvalidInput, match=message):
        catena.check_tension(columns, mooring_path)


def test_a_scene_without_a_motion_request_is_refused(mooring_path):
    with pytest.raises(catena.InvalidInput, match=r"the scene has no \[request\.motion\]"):
        catena.check_tension({"node": [0, 2], "nodes": [3, 3], "tension_std_n": [1.0, 2.0]}, mooring_path)


def test_a_csv_file_is_read_as_the_cli_reads_it(mooring_path, tmp_path):
    path = tmp_path / "sigma.csv"
    path.write_text("# other code\ns_m,tension_std_n\n0,5\n500,inf\n")
    with pytest.raises(catena.InvalidInput, match=r"row 2 \(line 4\), column 'tension_std_n'"):
        catena.check_tension(path, mooring_path)
    with pytest.raises(FileNotFoundError):
        catena.check_tension(tmp_path / "missing.csv", mooring_path)
    with pytest.raises(catena.InvalidInput, match="rtol"):
        catena.check_tension({"s_m": [0.0], "tension_std_n": [1.0]}, mooring_path, rtol=0.0)
