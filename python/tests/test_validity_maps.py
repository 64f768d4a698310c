# SPDX-License-Identifier: MIT
"""The validity maps' formulas and map builder (verification/tools/validity_maps.py,
docs/explanation/validity-maps.md): the taut-string and Irvine formulas against shooting where they
are exact to a known order, Irvine's equation against its known roots, and the map builder on a small
synthetic points.csv whose errors are known."""

import csv
import math
import sys

import numpy as np
import pytest

from conftest import SOURCE_DIR

import catena

sys.path.insert(0, str(SOURCE_DIR / "verification" / "tools"))
import validity_maps as vm  # noqa: E402

GROUPS = ("eps", "lambda2", "chord_angle_rad", "t0_n", "sag_parameter", "taut_frequency_scale_rad_s")


def shooting_and_cable(eps, phi_deg, lambda2):
    scene = {"name": "taut", "taut_inclined": {"eps": eps, "phi_deg": phi_deg, "lambda2": lambda2},
             "request": {"inplane_modes": 6, "outofplane_modes": 6}, "solvers": {"shooting": {"rtol": 1e-12}}}
    result = catena.solve(scene, checks=False)
    (out,) = result.outputs
    assert out.summary.status == "converged"
    cable = vm.cable_of({"groups." + key: getattr(result.groups, key) for key in GROUPS})
    # The chord the module derives from Gale's sag parameter is the problem's own.
    problem = catena.Problem.taut_inclined(eps=eps, phi_deg=phi_deg, lambda2=lambda2)
    assert cable["chord_m"] == pytest.approx(math.hypot(*problem.b_m), rel=1e-12)
    planes = {plane: [m.omega_rad_s for m in getattr(out, plane).modes] for plane in vm.PLANES}
    return planes, cable


def worst(formula, exact):
    return max(abs(a - b) / b for a, b in zip(formula, exact))


def test_string_is_shooting_out_of_plane_for_a_taut_cable():
    # eps = 1e-3: the weight's effect is O(eps^2) = 1e-6 x a small factor; the static strain
    # T0/EA = eps^2 cos^2(phi) / lambda^2 = 7.5e-7 shifts the string (chord, unstretched mass) by half
    # of it. Both well below 1e-6; a wrong chord, tension or mass would be off by O(eps) or more.
    planes, cable = shooting_and_cable(1e-3, 30.0, 1.0)
    string = vm.string_frequencies(cable["chord_m"], cable["tension_n"], cable["mass_kg_per_m"], 6)
    assert worst(string, planes["outofplane"]) < 1e-6
    # In plane lambda^2 = 1 moves the symmetric modes by percents: the string is not the answer...
    assert worst(string, planes["inplane"]) > 1e-2
    # ... Irvine's equation is.
    irvine = vm.irvine_inplane_frequencies(cable["chord_m"], cable["tension_n"], cable["mass_kg_per_m"],
                                           cable["lambda2"], 6)
    assert worst(irvine, planes["inplane"]) < 1e-6


@pytest.mark.parametrize("lambda2", [10.0, 4 * math.pi ** 2, 100.0])
def test_irvine_is_shooting_in_plane_for_a_shallow_level_cable(lambda2):
    planes, cable = shooting_and_cable(1e-3, 0.0, lambda2)  # sag/span 1.25e-4
    irvine = vm.irvine_inplane_frequencies(cable["chord_m"], cable["tension_n"], cable["mass_kg_per_m"],
                                           lambda2, 6)
    assert worst(irvine, planes["inplane"]) < 1e-6


def test_irvine_known_roots():
    # lambda^2 = 4 pi^2: the first symmetric root is x = pi, where w = 2 pi c / l equals the first
    # antisymmetric mode (Irvine's crossover).
    assert vm.irvine_symmetric_roots(4 * math.pi ** 2, 1)[0] == pytest.approx(math.pi, rel=1e-14)
    first, second = vm.irvine_inplane_frequencies(1.0, 1.0, 1.0, 4 * math.pi ** 2, 2)
    assert first == pytest.approx(2 * math.pi, rel=1e-14) and second == pytest.approx(2 * math.pi, rel=1e-14)
    # Inextensible: tan x = x, whose first roots are 4.4934094579090642 and 7.7252518369377072.
    roots = vm.irvine_symmetric_roots(math.inf, 2)
    assert roots == pytest.approx([4.4934094579090642, 7.7252518369377072], rel=1e-14)
    # lambda^2 -> 0: the taut string's symmetric modes x = (2n - 1) pi / 2, shifted by lambda^2 / (4 x^3).
    small = vm.irvine_symmetric_roots(1e-6, 3)
    for n, x in enumerate(small, start=1):
        string = (2 * n - 1) * math.pi / 2
        assert x - string == pytest.approx(1e-6 / (4 * string ** 3), rel=1e-5)
    # Each root solves the equation, and they ascend one per branch of tan.
    for lambda2 in (0.5, 20.0, 1e3):
        roots = vm.irvine_symmetric_roots(lambda2, 6)
        for n, x in enumerate(roots, start=1):
            assert (2 * n - 1) * math.pi / 2 < x < (2 * n + 1) * math.pi / 2
            assert math.tan(x) == pytest.approx(x - 4 * x ** 3 / lambda2, rel=1e-9, abs=1e-9)


def synthetic_points(path, size=9):
    """A level map whose 'shooting' is the string times 1 + e, e = 10^(-6 + 5 t) growing along the
    sag axis (t in [0, 1]), so the string's error is e / (1 + e): it crosses 1e-4, 1e-3 and 1e-2.
    One point has shooting unconverged (grey)."""
    columns = ["point", "shooting.status", "statics.sag_to_span"] + ["groups." + g for g in GROUPS] + [
        f"shooting.{p}.mode{k}.{q}" for p in vm.PLANES for k in range(1, 7)
        for q in ("omega_rad_s", "relative_error_estimate")]
    rows = []
    for i, lambda2 in enumerate(np.geomspace(0.1, 100.0, size)):
        for j, t in enumerate(np.linspace(0.0, 1.0, size)):
            e = 10.0 ** (-6.0 + 5.0 * t)
            row = {"point": len(rows), "shooting.status": "converged" if (i, j) != (4, 4) else "no-convergence",
                   "statics.sag_to_span": 1e-3 * 10.0 ** (2 * t), "groups.eps": 0.01, "groups.lambda2": lambda2,
                   "groups.chord_angle_rad": 0.0, "groups.t0_n": 1.0, "groups.sag_parameter": 1.0,
                   "groups.taut_frequency_scale_rad_s": 1.0}
            for plane in vm.PLANES:
                for k in range(1, 7):
                    row[f"shooting.{plane}.mode{k}.omega_rad_s"] = k * math.pi * (1 + e)
                    row[f"shooting.{plane}.mode{k}.relative_error_estimate"] = 1e-10
            rows.append(row)
    path.parent.mkdir(parents=True)
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns)
        writer.writeheader()
        writer.writerows(rows)


def test_map_builder_on_synthetic_points(tmp_path):
    synthetic_points(tmp_path / "validity" / "level" / "points.csv")
    data = vm.read_map(tmp_path / "validity" / "level" / "points.csv")
    errors = data["string"]["worst6"]
    sag = np.array([c["sag_to_span"] for c in data["cable"]])
    expected = 10.0 ** (-6.0 + 5.0 * np.log10(sag / 1e-3) / 2.0)
    grey = ~np.isfinite(errors)
    assert grey.sum() == 1  # the unconverged reference, and only it
    assert np.allclose(errors[~grey], expected[~grey] / (1 + expected[~grey]), rtol=1e-9)
    assert not np.isfinite(data["asymptotic"]["inplane1"]).any()  # no columns: grey, not zero

    # Where the string holds to 1 %: e / (1 + e) <= 1e-2 up to t = 0.75 on this grid (sag 10^-1.5),
    # in every column but the one whose grey point (t = 0.5) ends the run at the point before it
    # (t = 0.375, sag 10^-2.25).
    holds = vm.holds_up_to(data, "level", "string", "worst6", 1e-2)
    assert len(holds) == 9
    for index, (_, y, end) in enumerate(holds):
        assert y == pytest.approx(10.0 ** (-3 + (0.75 if index == 4 else 1.5)), rel=1e-12)
        assert end == ("grey" if index == 4 else "error")
    assert all(y is None and end == "grey" for _, y, end in vm.holds_up_to(data, "level", "airy", "inplane1", 1e-2))
    assert all(y == pytest.approx(0.1) and end == "edge"  # e <= 1e-1 everywhere: held to the map's edge
               for x, y, end in vm.holds_up_to(data, "level", "string", "outofplane1", 0.11) if x != holds[4][0])

    # The drawn panel has all three contours, and the figures land in index order with captions.
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    x = np.array([c["lambda2"] for c in data["cable"]])
    tri = vm.triangulation(x, sag, True, True)
    fig, ax = plt.subplots()
    image, lines = vm.draw_panel(ax, tri, errors, "string")
    assert image is not None
    assert [len(segments) > 0 for segments in lines.allsegs] == [True, True, True]
    plt.close(fig)
    out = tmp_path / "figures"
    out.mkdir()
    figures, notes = vm.draw_all(tmp_path / "validity", out, models=("string",))
    assert [name for name, _ in figures] == ["validity-map-level-string.png"]
    assert all((out / name).stat().st_size > 10000 for name, _ in figures)
    assert len(notes) == 1 and "inclined" in notes[0]  # no inclined sweep: said, not drawn


def test_a_refused_point_is_grey_not_a_number():
    # A point the scene refused has empty cells: no frequency, no error, for every model.
    empty = vm.cable_of({})
    for model in vm.MODELS:
        reference = {plane: [float(k) for k in range(1, 7)] for plane in vm.PLANES}  # shooting has values
        errors = vm.errors(reference, vm.model_modes({}, model, empty))
        assert all(math.isnan(e) for e in errors.values())
