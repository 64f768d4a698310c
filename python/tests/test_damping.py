# SPDX-License-Identifier: MIT
"""Damping from Python (docs/reference/python.md, "Damping"; docs/explanation/physics.md, "Damping"):
the inputs and their errors, the damped result fields on an undamped scene (lambda = i omega, no
decay, real shapes), their conversion from complex values a test chose, and proportional damping's
exact roots lambda = -alpha/2 +- i sqrt(omega0^2 - alpha^2/4) on a solver that handles damping."""

import json
import math
import subprocess

import numpy
import pytest

import catena
from catena import _catena
from catena._scene_dict import scene_toml_text

CABLE = dict(length_m=100.0, weight_n_per_m=10.0, mass_kg_per_m=2.0, axial_stiffness_n=1e7,
             added_mass_kg_per_m=1.0)
DAMPING = dict(damping_tangential_n_s_per_m2=0.2, damping_normal_n_s_per_m2=0.3, axial_damping_n_s=50.0)
# The scene key (and error message) of each Python keyword.
SCENE_KEY = {"damping_tangential_n_s_per_m2": "damping_tangential",
             "damping_normal_n_s_per_m2": "damping_normal", "axial_damping_n_s": "axial_damping"}
B = (99.0, 10.0)


def cable_scene(**extra):
    """A taut cable as a dict scene, with extra [cable] keys."""
    cable = {"length": 100.0, "weight": 10.0, "EA": 1e7, "mass": 2.0, "added_mass": 1.0, "a": [0.0, 0.0],
             "b": list(B), **extra}
    return {"name": "damped-taut", "cable": cable, "request": {"inplane_modes": 3, "outofplane_modes": 2}}


# --- inputs ---

def test_damping_is_zero_by_default_and_kept_as_given():
    undamped = catena.Cable(**CABLE)
    assert not undamped.damped and undamped.damping_normal_n_s_per_m2 == 0.0
    assert "damping" not in repr(undamped)  # an undamped repr is unchanged
    cable = catena.Cable(**CABLE, **DAMPING)
    assert cable.damped and all(getattr(cable, k) == v for k, v in DAMPING.items())
    problem = catena.Problem(cable, b_m=B)
    assert problem.damped and not catena.Problem(undamped, b_m=B).damped
    segment = catena.LineSegment(**CABLE, **DAMPING)
    assert segment.damped and all(getattr(segment, k) == v for k, v in DAMPING.items())
    line = catena.Line([catena.LineSegment(**CABLE), segment])
    assert line.damped and catena.Problem.from_line(line, b_m=(190.0, 20.0)).damped
    bed = catena.Seabed(0.0, stiffness_n_per_m2=1e5, damping_n_s_per_m2=7.0)
    assert bed.damping_n_s_per_m2 == 7.0
    assert catena.Problem(undamped, b_m=B, seabed=bed).damped


def test_python_cable_equals_the_scene_cable():
    scene = catena.load_scene(cable_scene(damping_tangential=0.2, damping_normal=0.3, axial_damping=50.0))
    cable = scene.problem.cable
    assert all(getattr(cable, k) == v for k, v in DAMPING.items())
    assert scene.problem.damped


@pytest.mark.parametrize("field", list(SCENE_KEY))
@pytest.mark.parametrize("value", [-1.0, math.nan, math.inf, -math.inf])
def test_bad_damping_is_a_value_error_naming_the_field(field, value):
    key = SCENE_KEY[field]
    with pytest.raises(ValueError, match=rf"cable\.{key} = "):
        catena.Cable(**CABLE, **{field: value})
    with pytest.raises(ValueError, match=rf"line\.segments\[0\]\.{key} = "):
        catena.LineSegment(**CABLE, **{field: value})
    with pytest.raises(ValueError, match=rf"\[cable\]\.{key} = "):
        catena.load_scene(cable_scene(**{key: value}))
    cable = catena.Cable(**CABLE)
    setattr(cable, field, value)  # bypassing the constructor is caught before any solve
    problem = catena.Problem(catena.Cable(**CABLE), b_m=B)
    problem.cable = cable
    with pytest.raises(ValueError, match=rf"cable\.{key} = "):
        catena.run_solver("fe", problem)


def test_axial_damping_of_an_inextensible_section_is_refused():
    inextensible = {**CABLE, "axial_stiffness_n": math.inf}
    with pytest.raises(ValueError, match=r"cable\.axial_damping = 1: an inextensible"):
        catena.Cable(**inextensible, axial_damping_n_s=1.0)
    with pytest.raises(ValueError, match=r"line\.segments\[0\]\.axial_damping = 1: an inextensible"):
        catena.LineSegment(**inextensible, axial_damping_n_s=1.0)
    with pytest.raises(ValueError, match=r"axial_damping = 1: an inextensible"):
        catena.load_scene(cable_scene(EA="inf", axial_damping=1.0))
    # drag alone is fine on an inextensible cable
    assert catena.Cable(**inextensible, damping_normal_n_s_per_m2=1.0).damped


@pytest.mark.parametrize("value", [-1.0, math.nan, math.inf])
def test_bad_seabed_damping_names_the_field(value):
    with pytest.raises(ValueError, match=r"seabed\.damping = "):
        catena.Seabed(0.0, damping_n_s_per_m2=value)
    scene = cable_scene()
    scene["seabed"] = {"z": 0.0, "damping": value}
    with pytest.raises(ValueError, match=r"\[seabed\]\.damping = "):
        catena.load_scene(scene)


GALE = {"xi1": -0.34, "xi2": 0.34}
TAUT = {"eps": 0.18, "phi_deg": 23.46, "lambda2": 38.0, "mass_ratio": 0.8}


def form_scene(form, values):
    return {"name": form, form: values, "request": {"inplane_modes": 2}}


def test_forms_take_their_nondimensional_damping_as_the_reader_does():
    # Gale's form has m = 1 kg/m, g = 1, a = 1 m, so c = eta m sqrt(g/a) = eta (eqs. 2.28e,f).
    python = catena.Problem.gale_xi(GALE["xi1"], GALE["xi2"], eta1=0.05, eta2=0.2).cable
    read = catena.load_scene(form_scene("gale", {**GALE, "eta1": 0.05, "eta2": 0.2})).problem.cable
    assert (python.damping_tangential_n_s_per_m2, python.damping_normal_n_s_per_m2) == (0.05, 0.2)
    assert (read.damping_tangential_n_s_per_m2, read.damping_normal_n_s_per_m2) == (0.05, 0.2)
    sag = catena.Problem.gale_sag(0.25, 0.8, eta1=0.05, eta2=0.2).cable
    read = catena.load_scene(form_scene("gale", {"h_over_b": 0.25, "sag_param": 0.8, "eta1": 0.05,
                                                 "eta2": 0.2})).problem.cable
    assert (sag.damping_tangential_n_s_per_m2, sag.damping_normal_n_s_per_m2) == \
        (read.damping_tangential_n_s_per_m2, read.damping_normal_n_s_per_m2) == (0.05, 0.2)
    # The taut form has L = 1 m, T0 = 1 N, M = 1 kg/m: c_t = eta_t sqrt(T0 M)/L = eta_t, c_a = eta_a.
    etas = {"eta_tangential": 0.01, "eta_normal": 0.3, "eta_axial": 0.002}
    python = catena.Problem.taut_inclined(**TAUT, **etas).cable
    read = catena.load_scene(form_scene("taut_inclined", {**TAUT, **etas})).problem.cable
    for cable in (python, read):
        assert cable.normal_mass_kg_per_m == pytest.approx(1.0, rel=1e-15)
        assert cable.damping_tangential_n_s_per_m2 == pytest.approx(0.01, rel=1e-15)
        assert cable.damping_normal_n_s_per_m2 == pytest.approx(0.3, rel=1e-15)
        assert cable.axial_damping_n_s == pytest.approx(0.002, rel=1e-15)
    assert [getattr(python, k) for k in DAMPING] == [getattr(read, k) for k in DAMPING]  # bit for bit


@pytest.mark.parametrize("value", [-0.1, math.nan, math.inf])
def test_bad_form_damping_names_the_eta(value):
    with pytest.raises(ValueError, match=r"gale_xi: eta2 = "):
        catena.Problem.gale_xi(GALE["xi1"], GALE["xi2"], eta2=value)
    with pytest.raises(ValueError, match=r"gale_sag: eta1 = "):
        catena.Problem.gale_sag(0.25, 0.8, eta1=value)
    with pytest.raises(ValueError, match=r"taut_inclined: eta_axial = "):
        catena.Problem.taut_inclined(**TAUT, eta_axial=value)
    with pytest.raises(ValueError, match=r"\[gale\]\.eta1 = "):
        catena.load_scene(form_scene("gale", {**GALE, "eta1": value}))
    with pytest.raises(ValueError, match=r"\[taut_inclined\]\.eta_normal = "):
        catena.load_scene(form_scene("taut_inclined", {**TAUT, "eta_normal": value}))


def test_given_statics_must_hold_the_problems_damping():
    # Damping does not change the statics, but a solver may read the line's dynamic coefficients
    # from the statics' copy of the line (shooting does): statics of another damping are refused.
    undamped = catena.Problem(catena.Cable(**CABLE), b_m=B)
    damped = catena.Problem(catena.Cable(**CABLE, **DAMPING), b_m=B)
    statics = catena.solve_statics(damped)
    assert statics.horizontal_force_n == catena.solve_statics(undamped).horizontal_force_n
    with pytest.raises(ValueError, match=r"statics: solved for another cable"):
        catena.run_solver("shooting", damped, statics=catena.solve_statics(undamped))
    with pytest.raises(ValueError, match=r"statics: solved for another cable"):
        catena.run_solver("shooting", undamped, statics=statics)
    catena.run_solver("shooting", damped, catena.Request(inplane_modes=1), statics=statics)  # accepted
    bed = dict(z_m=0.0, stiffness_n_per_m2=1e5)
    on_bed = catena.Problem(catena.Cable(**CABLE), b_m=B, seabed=catena.Seabed(**bed, damping_n_s_per_m2=5.0))
    other_bed = catena.Problem(catena.Cable(**CABLE), b_m=B, seabed=catena.Seabed(**bed))
    with pytest.raises(ValueError, match=r"statics: solved for another seabed"):
        catena.run_solver("shooting", on_bed, statics=catena.solve_statics(other_bed))


# --- results of an undamped scene: the damped fields say "no damping" ---

def test_undamped_results_have_imaginary_roots_and_real_shapes():
    forced = catena.ForcedRequest([0.5], direction="normal", amplitude_m=0.01)
    request = catena.Request(inplane_modes=3, outofplane_modes=2, shapes=True, points=21, tension=True,
                             forced=forced)
    out = catena.solve_shooting(catena.Problem(catena.Cable(**CABLE), b_m=B), request)
    assert out.summary.status == "converged"
    for modes in (out.inplane, out.outofplane):
        assert modes.eigenvalue.dtype == numpy.complex128
        assert numpy.array_equal(modes.eigenvalue, 1j * modes.omega_rad_s)
        assert not numpy.signbit(modes.eigenvalue.real).any()  # 0, not -0
        assert numpy.array_equal(modes.decay_rate_1_s, numpy.zeros(len(modes)))
        assert numpy.array_equal(modes.damping_ratio, numpy.zeros(len(modes)))
        assert numpy.isnan(modes.decay_rate_error_estimate).all()
        assert len(modes.overdamped) == 0 and modes.overdamped.eigenvalue.shape == (0,)
        mode = modes.modes[0]
        assert mode.eigenvalue == 1j * mode.omega_rad_s and mode.decay_rate_1_s == 0.0
        assert mode.damping_ratio == 0.0 and mode.decay_rate_error_estimate is None
        assert "decay" not in repr(mode)
        shapes = modes.shapes
        for table in (shapes.u, shapes.w, shapes.v, shapes.tension_n):
            assert table is None or table.dtype == numpy.float64
        for field in ("u", "w", "v", "tension_n"):
            assert getattr(mode, field).dtype == numpy.float64
    response = out.forced[0]
    assert response.diagnostic == ""
    for field in ("u_m", "w_m", "v_m", "tension_n"):
        assert getattr(response, field).dtype == numpy.float64


# --- the conversion of damped values, from values this test chose ---

def test_damped_values_become_complex_arrays():
    s_m = [0.0, 0.5, 1.0]
    roots = [-0.1 + 2.0j, -0.3 + 5.0j]
    u = [[0.0, 0.1 - 0.2j, 0.0], [0.0, 0.3j, 0.0]]
    w = [[0.0, 1.0 + 0.0j, 0.0], [0.0, -0.5 + 0.5j, 0.0]]
    tension = [[10.0 + 1.0j, 20.0 - 2.0j, 30.0], [-4.0j, 5.0, 6.0 + 6.0j]]
    out = _catena._synthetic_damped_output(roots, s_m, u, w, tension, [0.7, 4.0], 1.5, [0.0, 0.2 + 0.1j, 0.0])
    modes = out.inplane
    assert modes.eigenvalue.tolist() == roots
    assert modes.omega_rad_s.tolist() == [2.0, 5.0] and modes.decay_rate_1_s.tolist() == [0.1, 0.3]
    assert modes.damping_ratio.tolist() == [0.1 / abs(roots[0]), 0.3 / abs(roots[1])]
    assert numpy.isnan(modes.decay_rate_error_estimate).all()
    for k, mode in enumerate(modes.modes):
        assert mode.eigenvalue == roots[k]
        assert mode.u.tolist() == u[k] and mode.w.tolist() == w[k] and mode.tension_n.tolist() == tension[k]
        assert mode.w.dtype == numpy.complex128 and not mode.w.flags.writeable
        assert "decay_rate_1_s=" in repr(mode)
    # tables: stations x modes, column k is mode k + 1
    shapes = modes.shapes
    assert shapes.w.dtype == numpy.complex128 and shapes.w.shape == (3, 2)
    assert shapes.u.T.tolist() == u and shapes.w.T.tolist() == w and shapes.tension_n.T.tolist() == tension
    assert shapes.v is None and not shapes.w.flags.writeable
    # overdamped roots: real lambda = -delta, apart from the modes, with the same fields
    roots_apart = modes.overdamped
    assert len(roots_apart) == 2 and roots_apart.plane == "in-plane"
    assert roots_apart.eigenvalue.tolist() == [-0.7 + 0j, -4.0 + 0j]
    assert roots_apart.decay_rate_1_s.tolist() == [0.7, 4.0]
    assert roots_apart.damping_ratio.tolist() == [1.0, 1.0] and roots_apart.omega_rad_s.tolist() == [0.0, 0.0]
    assert len(roots_apart.overdamped) == 0 and roots_apart.proved_count_below_top is None
    response = out.forced[0]
    assert response.w_m.tolist() == [0.0, 0.2 + 0.1j, 0.0] and response.w_m.dtype == numpy.complex128
    assert response.u_m.dtype == numpy.float64 and response.u_m.shape == (0,)  # not computed: empty


# --- a damped scene solved (runs once a solver handles damping) ---

def proportional_scene(alpha, **request):
    """Proportional damping c_t = alpha m, c_n = alpha (m + ma), c_a = 0 on the taut cable."""
    scene = cable_scene(damping_tangential=alpha * CABLE["mass_kg_per_m"],
                        damping_normal=alpha * (CABLE["mass_kg_per_m"] + CABLE["added_mass_kg_per_m"]))
    scene["request"].update(request)
    scene["solvers"] = {"fe": {}, "shooting": {}}
    return scene


def damped_solvers(result):
    """The solvers whose every plane converged on the damped scene; skips the test when none did."""
    names = [name for name in result.solvers if result[name].summary.status == "converged"]
    if not names:
        reasons = "; ".join(f"{n}: {result[n].summary.message}" for n in result.solvers)
        pytest.skip(f"no solver handles damping on this build yet ({reasons})")
    return names


def predicted_roots(omega0, alpha):
    """Proportional damping's exact roots for the undamped frequency omega0: the oscillating root, or
    the two overdamped ones (docs/explanation/physics.md, "Damping")."""
    if omega0 > alpha / 2:
        return [complex(-alpha / 2, math.sqrt(omega0**2 - alpha**2 / 4))]
    root = math.sqrt(alpha**2 / 4 - omega0**2)
    return [complex(-alpha / 2 + root, 0.0), complex(-alpha / 2 - root, 0.0)]


def test_proportional_damping_gives_the_exact_roots_and_undamped_shapes():
    undamped = catena.solve(proportional_scene(0.0, shapes=True, points=21), checks=False)
    alpha = 0.2 * undamped["shooting"].inplane.omega_rad_s[0]
    result = catena.solve(proportional_scene(alpha, shapes=True, points=21), checks=False)
    for name in damped_solvers(result):
        for plane in ("inplane", "outofplane"):
            modes, reference = getattr(result[name], plane), getattr(undamped[name], plane)
            assert len(modes) == len(reference) and len(modes.overdamped) == 0
            expected = numpy.array([predicted_roots(w0, alpha)[0] for w0 in reference.omega_rad_s])
            # relative to each root: the solvers' targets at their defaults are far below 1e-6
            assert numpy.allclose(modes.omega_rad_s, expected.imag, rtol=1e-6, atol=0.0), name
            assert numpy.allclose(modes.decay_rate_1_s, alpha / 2, rtol=1e-6, atol=0.0), name
            assert numpy.allclose(modes.eigenvalue, modes.omega_rad_s * 1j - modes.decay_rate_1_s, rtol=0, atol=0)
            assert numpy.allclose(modes.damping_ratio, (alpha / 2) / numpy.abs(expected), rtol=1e-6), name
            # the damping is proportional: the damped shapes are the undamped (real) ones
            field = "w" if plane == "inplane" else "v"
            damped_shape, undamped_shape = getattr(modes.shapes, field), getattr(reference.shapes, field)
            assert numpy.iscomplexobj(damped_shape), name
            assert numpy.allclose(damped_shape, undamped_shape, rtol=0.0, atol=1e-6), name


def test_overdamped_roots_are_listed_apart():
    undamped = catena.solve(proportional_scene(0.0), checks=False)
    omega0 = undamped["shooting"].inplane.omega_rad_s
    alpha = 1.01 * (omega0[0] + omega0[1])  # between 2 omega0_1 and 2 omega0_2: mode 1 overdamped
    result = catena.solve(proportional_scene(alpha), checks=False)
    for name in damped_solvers(result):
        modes = result[name].inplane
        expected_first = predicted_roots(undamped[name].inplane.omega_rad_s[1], alpha)[0]
        assert modes.eigenvalue[0] == pytest.approx(expected_first, rel=1e-6), name
        slow, fast = predicted_roots(undamped[name].inplane.omega_rad_s[0], alpha)
        roots = modes.overdamped.eigenvalue
        assert len(roots) >= 1 and roots[0] == pytest.approx(slow, rel=1e-6), name
        assert (modes.overdamped.damping_ratio == 1.0).all() and (modes.overdamped.omega_rad_s == 0.0).all()
        if len(roots) > 1:
            assert numpy.all(numpy.diff(modes.overdamped.decay_rate_1_s) > 0), name


# --- the CLI and the JSON document ---

def test_json_of_a_damped_scene_carries_the_damping(cli, tmp_path):
    scene = cable_scene(damping_tangential=0.2, damping_normal=0.3, axial_damping=50.0)
    scene["seabed"] = {"z": 0.0, "stiffness": 1e5, "damping": 7.0}
    scene["request"]["shapes"] = True
    result = catena.solve(scene, checks=False)
    document = json.loads(result.to_json())["scenes"][0]
    problem = document["problem"]
    assert problem["cable"]["damping"] == {"tangential_n_s_per_m2": 0.2, "normal_n_s_per_m2": 0.3,
                                           "axial_n_s": 50.0}
    assert problem["seabed"]["damping_n_s_per_m2"] == 7.0
    path = tmp_path / "damped.toml"
    path.write_text(scene_toml_text(scene))
    out = tmp_path / "out.json"
    text = subprocess.run([cli, "solve", str(path), "--verbose", "--json", str(out)], check=True,
                          capture_output=True, text=True).stdout
    assert "damping: c_t = 0.2 N s/m per m, c_n = 0.3 N s/m per m, c_a = 50 N s" in text
    assert json.loads(out.read_text())["scenes"][0]["problem"] == problem
    # Each converged solver's modes carry delta and zeta in the JSON and in the text table.
    for name, solver in document["solvers"].items():
        if result[name].inplane is None or len(result[name].inplane) == 0:
            continue
        assert "damped: omega_d = Im lambda" in text and "delta [1/s]" in text
        for k, mode in enumerate(solver["inplane"]["modes"]):
            assert mode["decay_rate_1_s"] == result[name].inplane.decay_rate_1_s[k]
            assert mode["damping_ratio"] == result[name].inplane.damping_ratio[k]
            shape = mode["shape"]
            assert shape["w_imag"] == result[name].inplane.modes[k].w.imag.tolist()


def test_json_of_an_undamped_mode_has_zero_decay_and_no_imaginary_parts(mooring_path):
    document = json.loads(catena.solve(mooring_path, solvers=["shooting"], checks=False).to_json())
    problem = document["scenes"][0]["problem"]
    assert "damping" not in problem["cable"]
    for mode in document["scenes"][0]["solvers"]["shooting"]["inplane"]["modes"]:
        assert mode["decay_rate_1_s"] == 0.0 and mode["damping_ratio"] == 0.0
        assert "decay_rate_error_estimate" not in mode
