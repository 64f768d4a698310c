# SPDX-License-Identifier: MIT
"""The module is the library the CLI runs: the mooring scene gives, to the last digit, what
`catena solve --json` writes."""

import json
import re
import subprocess

import catena


def cli_json(cli, scene, tmp_path):
    out = tmp_path / "out.json"
    subprocess.run([cli, "solve", str(scene), "--json", str(out), "--quiet"], check=True)
    return json.loads(out.read_text())["scenes"][0]


def test_mooring_frequencies_equal_cli_json(cli, mooring_path, tmp_path):
    expected = cli_json(cli, mooring_path, tmp_path)
    result = catena.solve(mooring_path)
    assert result.statics.horizontal_force_n == expected["statics"]["horizontal_force_n"]
    assert result.statics.vertical_force_a_n == expected["statics"]["vertical_force_a_n"]
    assert sorted(result.solvers) == sorted(expected["solvers"])
    compared = 0
    for name, solver in expected["solvers"].items():
        assert result[name].summary.status == solver["summary"]["termination"]
        for plane in ("inplane", "outofplane"):
            if plane not in solver or solver[plane] is None:
                assert getattr(result[name], plane) is None
                continue
            modes = getattr(result[name], plane)
            omegas = [mode["omega_rad_s"] for mode in solver[plane]["modes"]]
            assert modes.omega_rad_s.tolist() == omegas  # exact: the same doubles
            assert modes.frequency_hz.tolist() == [mode["frequency_hz"] for mode in solver[plane]["modes"]]
            compared += len(omegas)
    assert compared >= 24  # fe and shooting at least, 6 + 6 modes each


def without_times(node):
    """The document with its measured times (fields, and durations quoted in messages) removed."""
    if isinstance(node, dict):
        return {k: without_times(v) for k, v in node.items() if k not in ("wall_time_s", "brief")}
    if isinstance(node, list):
        return [without_times(v) for v in node]
    if isinstance(node, str):
        return re.sub(r"\d+(\.\d+)? (ms|us|s)\b", "<time>", node)
    return node


def test_result_json_equals_cli_json_except_times(cli, mooring_path, tmp_path):
    expected = cli_json(cli, mooring_path, tmp_path)
    ours = json.loads(catena.solve(mooring_path).to_json())["scenes"][0]

    assert without_times(ours) == without_times(expected)
