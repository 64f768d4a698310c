# SPDX-License-Identifier: MIT
"""Result.plot() (python/catena/_plot.py) and the pictures of `catena plot` / `catena solve --plot`
(docs/how-to/plot.md). The lines drawn are compared with the result itself: the profile with
Statics.position_m at the stations, the tension with Statics.tension_n, the out-of-plane curves with
the reference solver's shapes. The SVG must parse as XML; in a headless Chromium (skipped where it
is not installed, as tests/verification/report_browser_test.py does) its screenshot must not be
blank. The PNG goes through matplotlib."""

import copy
import pathlib
import re
import shutil
import subprocess
import tempfile
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import catena

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

# Two segments over a seabed, a clump weight and a buoy (as tests/io/scene_picture_test.cpp).
LINE = {
    "name": "picture-line",
    "line": {"a": [0.0, -200.0], "b": [780.0, -20.0],
             "segments": [{"length": 400.0, "weight": 1000.0, "EA": 1.0e9, "mass": 120.0, "added_mass": 20.0},
                          {"length": 500.0, "weight": 300.0, "EA": 5.0e8, "mass": 40.0, "added_mass": 8.0}],
             "points": [{"s": 600.0, "mass": 3000.0, "weight": 20000.0},
                        {"s": 750.0, "mass": 2000.0, "weight": -30000.0}]},
    "seabed": {"z": -200.0},
    "request": {"inplane_modes": 3, "outofplane_modes": 2, "points": 121, "shapes": True},
    "solvers": {"shooting": {}},
}


@pytest.fixture(scope="module")
def result():
    return catena.solve(LINE)


def by_role(ax, role):
    return [line for line in ax.get_lines() if line.get_gid() == role]


def test_profile_lines_are_the_statics_at_the_stations(result):
    ax = result.plot()
    segments = by_role(ax, "segment")
    assert len(segments) == 2
    stations = np.linspace(0.0, 900.0, 121)  # the request's 121 stations
    for line, (begin, end) in zip(segments, [(0.0, 400.0), (400.0, 900.0)]):
        # Between its two ends (placed exactly: an end of the line, the joint), a segment's path
        # runs through the profile's stations inside it.
        x, z = np.asarray(line.get_xdata()), np.asarray(line.get_ydata())
        expected = result.statics.position_m(stations[(stations > begin) & (stations < end)])
        # The stations' s may round differently here (an ulp of s): far below 1e-9 m.
        np.testing.assert_allclose(x[1:-1], expected[:, 0], rtol=0, atol=1e-9)
        np.testing.assert_allclose(z[1:-1], expected[:, 1], rtol=0, atol=1e-9)
        np.testing.assert_allclose([x[0], z[0]], result.statics.position_m([begin])[0], rtol=0, atol=1e-9)
        np.testing.assert_allclose([x[-1], z[-1]], result.statics.position_m([end])[0], rtol=0, atol=1e-9)
    seabed = by_role(ax, "seabed")
    assert len(seabed) == 1 and seabed[0].get_ydata()[0] == -200.0
    modes = by_role(ax, "mode")
    frequencies = result["shooting"].inplane.frequency_hz
    assert len(modes) == 3
    for k, line in enumerate(modes):
        # The label carries the reference's frequency; the ends stay at the supports.
        assert float(re.search(r": ([0-9.e+-]+) Hz", line.get_label()).group(1)) == pytest.approx(
            frequencies[k], rel=1e-4)
        # The shapes vanish at the supports up to the solver's own residual (about 1e-10 of the
        # normalised peak, drawn at 8 % of the 780 m extent): far below 1e-4 m.
        assert (line.get_xdata()[0], line.get_ydata()[0]) == pytest.approx((0.0, -200.0), abs=1e-4)
        assert (line.get_xdata()[-1], line.get_ydata()[-1]) == pytest.approx((780.0, -20.0), abs=1e-4)


def test_outofplane_and_tension_panels_hold_the_results_numbers(result):
    ax = result.plot(plane="out-of-plane", modes="all")
    shapes = result["shooting"].outofplane.shapes
    modes = by_role(ax, "mode")
    assert len(modes) == 2
    for k, line in enumerate(modes):
        np.testing.assert_array_equal(line.get_xdata(), shapes.s_m)
        np.testing.assert_array_equal(line.get_ydata(), shapes.v[:, k])
    fig, ax = matplotlib.pyplot.subplots()
    assert result.plot(ax=ax, plane="tension") is ax
    s = np.concatenate([line.get_xdata() for line in by_role(ax, "tension")])
    t = np.concatenate([line.get_ydata() for line in by_role(ax, "tension")])
    # At the stations, T(s) [kN] is the statics' tension (the joint at 400 m, between stations, is
    # interpolated and left out).
    k = s / 7.5
    at_station = np.abs(k - np.round(k)) < 1e-9
    assert at_station.sum() == 121  # each station once
    np.testing.assert_allclose(t[at_station], result.statics.tension_n(s[at_station]) / 1e3, rtol=1e-12)


def test_plot_refuses_what_it_cannot_draw(result):
    scene = copy.deepcopy(LINE)
    scene["request"]["shapes"] = False
    with pytest.raises(catena.InvalidInput, match="shapes = true"):
        catena.solve(scene).plot()
    with pytest.raises(catena.InvalidInput, match="plane"):
        result.plot(plane="plan")
    scene = copy.deepcopy(LINE)
    scene["request"]["outofplane_modes"] = 0
    with pytest.raises(catena.InvalidInput, match="out-of-plane"):
        catena.solve(scene).plot(plane="out-of-plane")


def test_cli_svg_is_xml_and_renders_in_a_browser(cli, tmp_path):
    scene = tmp_path / "line.toml"
    scene.write_text(pathlib.Path(__file__).parent.joinpath("..", "..", "verification", "scenes", "physical",
                                                            "mooring-line-900m.toml").read_text())
    svg = tmp_path / "mooring.svg"
    subprocess.run([cli, "solve", str(scene), "--plot", str(svg), "-q"], check=True)
    root = ET.parse(svg).getroot()
    assert root.tag.endswith("svg")
    roles = [e.get("class") for e in root.iter() if e.tag.endswith("polyline")]
    assert roles.count("segment") == 1 and roles.count("mode") == 6
    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    if not browser:
        pytest.skip("chromium is not installed (apt-get install chromium to run this part)")
    shot = tmp_path / "shot.png"
    with tempfile.TemporaryDirectory() as profile:
        subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                        "--disable-background-networking", "--disable-component-update", "--disable-sync",
                        f"--user-data-dir={profile}", "--window-size=960,900", f"--screenshot={shot}",
                        svg.as_uri()], capture_output=True, timeout=120, check=False)
    image = matplotlib.pyplot.imread(shot)[..., :3]
    dark = np.mean(np.min(image, axis=2) < 0.5)
    # Lines, text and markers on white: a blank or failed render has no dark pixels.
    assert dark > 0.005, f"{dark:.4f} of the screenshot is dark"


def test_cli_png_through_matplotlib(cli, tmp_path, mooring_path):
    out = tmp_path / "mooring.png"
    subprocess.run([cli, "solve", str(mooring_path), "--plot", str(out), "--plot-modes", "1", "-q"], check=True)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
