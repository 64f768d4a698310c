# SPDX-License-Identifier: MIT
"""numpy arrays of results own their memory: they stay valid after the result is freed."""

import gc

import numpy

import catena


def shapes_scene(mooring_dict):
    mooring_dict["request"].update(shapes=True, points=51, tension=True)
    mooring_dict["solvers"] = {"fe": {}, "shooting": {}}
    return mooring_dict


def test_shapes_are_stations_by_modes(mooring_dict):
    result = catena.solve(shapes_scene(mooring_dict))
    inplane, outofplane = result["shooting"].inplane, result["shooting"].outofplane
    shapes = inplane.shapes
    assert shapes.s_m.shape == (51,) and shapes.s_m[-1] == 1000.0
    assert shapes.u.shape == shapes.w.shape == shapes.tension_n.shape == (51, 6)
    assert shapes.v is None and outofplane.shapes.u is None and outofplane.shapes.v.shape == (51, 6)
    # normalised to max |w| = 1 per mode, column k is mode k + 1
    assert numpy.allclose(numpy.abs(shapes.w).max(axis=0), 1.0)
    assert shapes.w[:, 2].tolist() == inplane.modes[2].w.tolist()
    assert inplane.modal_mass_kg.shape == (6,) and inplane.max_abs_tension_n.shape == (6,)


def test_arrays_outlive_the_result(mooring_dict):
    result = catena.solve(shapes_scene(mooring_dict))
    omega = result["fe"].inplane.omega_rad_s
    w = result["fe"].inplane.shapes.w
    mode_u = result["fe"].inplane.modes[0].u
    expected = (omega.copy(), w.copy(), mode_u.copy())
    for array in (omega, w, mode_u):
        assert array.flags.owndata or array.base is not None
        assert not array.flags.writeable
    del result
    gc.collect()
    # reuse the freed memory, then look again
    junk = [catena.solve(shapes_scene(dict(mooring_dict))) for _ in range(2)]
    junk.append(numpy.full(100000, -7.0))
    gc.collect()
    assert numpy.array_equal(omega, expected[0])
    assert numpy.array_equal(w, expected[1])
    assert numpy.array_equal(mode_u, expected[2])


def test_nested_objects_outlive_their_parents(mooring_dict):
    result = catena.solve(shapes_scene(mooring_dict))
    modes = result["shooting"].inplane
    first = modes.modes[0]
    summary = modes.summary
    omega_first = first.omega_rad_s
    del result
    gc.collect()
    junk = [numpy.full(10000, 3.0) for _ in range(50)]
    assert first.omega_rad_s == omega_first == modes.omega_rad_s[0]
    assert summary.status == "converged" and len(junk) == 50
    assert first.w.shape == (51,)
