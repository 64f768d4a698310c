# SPDX-License-Identifier: MIT
"""A dict scene goes through the same reader as a file: same results, same field names in errors."""

import numpy
import pytest

import catena
from conftest import modal_values


def test_dict_and_file_scenes_agree(mooring_path, mooring_dict):
    from_file = catena.solve(mooring_path)
    from_dict = catena.solve(mooring_dict)
    assert from_dict.name == "mooring-line-900m"
    assert modal_values(from_dict) == modal_values(from_file)
    assert [c.verdict for c in from_dict.checks] == [c.verdict for c in from_file.checks]


def test_dict_accepts_numpy_values_and_tuples(mooring_dict):
    mooring_dict["cable"]["length"] = numpy.float64(1000.0)
    mooring_dict["cable"]["b"] = numpy.array([900.0, 300.0])
    mooring_dict["cable"]["a"] = (0, 0)
    mooring_dict["request"]["inplane_modes"] = numpy.int64(6)
    mooring_dict["solvers"] = {"fe": {"elements": numpy.int32(200), "richardson": numpy.bool_(True)}}
    result = catena.solve(mooring_dict)
    assert result.solvers == ["fe"]
    assert len(result["fe"].inplane) == 6


def error_of(scene):
    with pytest.raises(catena.InvalidInput) as caught:
        catena.solve(scene)
    return str(caught.value)


@pytest.mark.parametrize("table, key, value, expected", [
    ("cable", "length", -1.0, "[cable].length = -1: must be finite and > 0 [m]"),
    ("cable", "mass", float("nan"), "[cable].mass = nan: must be finite and > 0 [kg/m]"),
    ("cable", "EA", "stiff", "[cable].EA = \"stiff\": must be a number > 0 or \"inf\" [N]"),
    ("cable", "weight", "heavy", "[cable].weight: expected a number, got string"),
    ("cable", "lenght", 1000.0, "[cable].lenght"),
    ("request", "inplane_modes", 5000, "[request].inplane_modes = 5000: must be an integer in [0, 1000]"),
    ("request", "points", 1.5, "[request].points"),
])
def test_bad_values_name_the_same_field_in_dict_and_file(mooring_path, mooring_dict, tmp_path,
                                                         table, key, value, expected):
    mooring_dict[table][key] = value
    toml_value = {float: lambda v: "nan" if v != v else repr(v), str: lambda v: f'"{v}"',
                  int: str}[type(value)](value)
    text = mooring_path.read_text()
    if any(line.startswith(f"{key} = ") for line in text.splitlines()):
        text = "\n".join(f"{key} = {toml_value}" if line.startswith(f"{key} = ") else line
                         for line in text.splitlines())
    else:
        text = text.replace(f"[{table}]\n", f"[{table}]\n{key} = {toml_value}\n")
    bad_file = tmp_path / "bad.toml"
    bad_file.write_text(text)
    dict_message, file_message = error_of(mooring_dict), error_of(bad_file)
    assert expected in dict_message
    assert expected in file_message
    assert dict_message.startswith("<dict>:")
    assert dict_message.removeprefix("<dict>") == file_message.removeprefix(str(bad_file))


@pytest.mark.parametrize("value, kind", [(None, "NoneType"), (object(), "object"), ({1, 2}, "set")])
def test_values_toml_cannot_hold_name_the_key_path(mooring_dict, value, kind):
    mooring_dict["cable"]["length"] = value
    with pytest.raises(catena.ParseError, match=rf"<dict>\['cable'\]\['length'\]: a {kind} is not a scene value"):
        catena.solve(mooring_dict)


def test_huge_integers_cyclic_dicts_and_odd_keys_raise(mooring_dict):
    mooring_dict["request"]["inplane_modes"] = 2**70
    with pytest.raises(catena.ParseError, match=r"\['request'\]\['inplane_modes'\] = \d+: out of the range"):
        catena.solve(mooring_dict)
    cyclic = {"cable": {}}
    cyclic["cable"]["self"] = cyclic
    with pytest.raises(catena.ParseError, match="nested deeper than 64"):
        catena.solve(cyclic)
    with pytest.raises(catena.ParseError, match="keys must be strings"):
        catena.solve({1: 2})
    mooring_dict["request"]["inplane_modes"] = 6
    mooring_dict["cable"]["a.b"] = 1  # a quoted key with a dot is one (unknown) key, not a path
    with pytest.raises(catena.ParseError, match=r"\[cable\]\.a\.b"):
        catena.solve(mooring_dict)


def test_sweep_dict_gives_one_scene_per_value(mooring_dict):
    mooring_dict["sweep"] = {"parameter": "cable.length", "values": [1000.0, 1100.0]}
    mooring_dict["solvers"] = {"fe": {}}
    with pytest.raises(catena.InvalidInput, match="use catena.load_scenes or catena.solve_sweep"):
        catena.solve(mooring_dict)
    results = catena.solve_sweep(mooring_dict)
    assert [r.name for r in results] == ["mooring-line-900m[length=1000]", "mooring-line-900m[length=1100]"]
    assert results[1]["fe"].inplane.omega_rad_s[0] < results[0]["fe"].inplane.omega_rad_s[0]
