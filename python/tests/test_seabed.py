# SPDX-License-Identifier: MIT
"""A seabed built in Python (catena.Seabed) gives the statics of the same [seabed] scene, and bad
seabed values are a ValueError naming the field (docs/reference/python.md, "Seabed")."""

import pytest

import catena

CHAIN = dict(length_m=1000.0, weight_n_per_m=1200.0, axial_stiffness_n=8.0e8, mass_kg_per_m=150.0,
             added_mass_kg_per_m=20.0)
A, B = (0.0, -200.0), (955.85, 0.0)


def scene(friction):
    return {"name": "grounded", "cable": {"length": 1000.0, "weight": 1200.0, "EA": 8.0e8, "mass": 150.0,
                                          "added_mass": 20.0, "a": list(A), "b": list(B)},
            "seabed": {"z": A[1], "friction": friction, "stiffness": 3.0e6},
            "request": {"inplane_modes": 0, "outofplane_modes": 0}}


@pytest.mark.parametrize("friction", [0.0, 0.1])
def test_seabed_problem_has_the_scene_statics(friction):
    seabed = catena.Seabed(A[1], friction=friction, stiffness_n_per_m2=3.0e6)
    problem = catena.Problem(catena.Cable(**CHAIN), b_m=B, a_m=A, seabed=seabed)
    assert problem.seabed.friction == friction
    statics = catena.solve_statics(problem)
    reference = catena.solve(scene(friction)).statics
    assert statics.has_contact and 0.35 * 1000.0 < statics.grounded_length_m < 0.45 * 1000.0
    assert statics.grounded_length_m == reference.grounded_length_m
    assert statics.horizontal_force_n == reference.horizontal_force_n
    # Friction takes C_B w L_g off the anchor's load, never more than H.
    expected = max(statics.horizontal_force_n - friction * CHAIN["weight_n_per_m"] * statics.grounded_length_m, 0.0)
    assert statics.anchor_horizontal_force_n == pytest.approx(expected, rel=1e-12)
    # The grounded part lies on the seabed, straight and horizontal.
    positions = statics.position_m([0.0, 0.5 * statics.grounded_length_m])
    assert positions[0][1] == pytest.approx(A[1], abs=1e-9) and positions[1][1] == pytest.approx(A[1], abs=1e-9)


def test_statics_without_the_seabed_is_refused_for_a_seabed_problem():
    cable = catena.Cable(**CHAIN)
    problem = catena.Problem(cable, b_m=B, a_m=A, seabed=catena.Seabed(A[1]))
    free = catena.solve_statics(catena.Problem(cable, b_m=B, a_m=A))
    with pytest.raises(catena.InvalidInput, match="seabed"):
        catena.run_solver("fe", problem, statics=free)


@pytest.mark.parametrize("kwargs, field", [
    (dict(z_m=float("nan")), "seabed.z"),
    (dict(z_m=0.0, friction=-0.1), "seabed.friction"),
    (dict(z_m=0.0, stiffness_n_per_m2=-1.0), "seabed.stiffness"),
])
def test_bad_seabed_is_a_value_error_naming_the_field(kwargs, field):
    with pytest.raises(ValueError, match=field.replace(".", r"\.")):
        catena.Seabed(**kwargs)


def test_an_anchor_below_the_seabed_is_refused():
    with pytest.raises(ValueError, match=r"seabed\.z"):
        catena.Problem(catena.Cable(**CHAIN), b_m=B, a_m=(0.0, -210.0), seabed=catena.Seabed(-200.0))


def test_a_u_shape_has_one_contact_interval_between_its_hanging_ends():
    # Both ends 20 m below the surface, 1200 m of chain over 800 m in 300 m of water: each end hangs
    # to the seabed and the middle lies on it (docs/explanation/physics.md, "Seabed contact").
    cable = catena.Cable(**dict(CHAIN, length_m=1200.0))
    problem = catena.Problem(cable, b_m=(800.0, -20.0), a_m=(0.0, -20.0), seabed=catena.Seabed(-300.0))
    statics = catena.solve_statics(problem)
    assert not statics.anchor_grounded and statics.slack_length_m == 0.0
    [(begin, end)] = statics.contact_intervals
    assert begin == pytest.approx(1200.0 - end, rel=1e-12)
    assert statics.grounded_length_m == pytest.approx(end - begin, rel=1e-14)
    assert statics.position_m([0.5 * (begin + end)])[0][1] == pytest.approx(-300.0, abs=1e-9)


def test_a_slack_line_has_no_horizontal_force_and_a_heap():
    # 890 m of chain from an anchor 400 m away in 300 m of water (MoorPy tests/case5.dat).
    cable = catena.Cable(**dict(CHAIN, length_m=890.0))
    problem = catena.Problem(cable, b_m=(0.0, 0.0), a_m=(-400.0, -300.0), seabed=catena.Seabed(-300.0))
    statics = catena.solve_statics(problem)
    assert statics.horizontal_force_n == 0.0 and statics.anchor_grounded
    [(begin, end)] = statics.contact_intervals
    assert statics.slack_length_m == pytest.approx(end - begin - 400.0, rel=1e-12)


def test_a_seabed_stiffness_beyond_double_precision_is_refused_naming_the_field():
    # k = 1e24 N/m per m made shooting's memory grow without bound, time_limit_s or not (issue 32):
    # k L^2 / W is bounded by 1e16 (here k <= 1.2e16 N/m per m), in a scene and in Python alike.
    big = scene(0.0)
    big["seabed"]["stiffness"] = 1.0e24
    with pytest.raises(catena.InvalidInput, match=r"seabed\.stiffness = 1e\+24"):
        catena.solve(big, time_limit_s=10.0)
    with pytest.raises(ValueError, match=r"seabed\.stiffness"):
        catena.Problem(catena.Cable(**CHAIN), b_m=B, a_m=A,
                       seabed=catena.Seabed(A[1], stiffness_n_per_m2=1.0e24))
