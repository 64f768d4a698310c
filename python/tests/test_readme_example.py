# SPDX-License-Identifier: MIT
"""The README's Python example runs as written (matplotlib drawing off screen)."""

import os

import matplotlib

from conftest import SOURCE_DIR


def readme_example():
    lines = (SOURCE_DIR / "README.md").read_text().splitlines()
    start = lines.index("# PYTHONPATH=build/python /usr/bin/python3") + 1
    end = lines.index("```", start)
    return "\n".join(lines[start:end])


def test_readme_example_runs(tmp_path):
    matplotlib.use("Agg")
    namespace = {}
    cwd = os.getcwd()
    os.chdir(SOURCE_DIR)  # the example names a scene relative to the repository
    try:
        exec(compile(readme_example(), "README.md", "exec"), namespace)
    finally:
        os.chdir(cwd)
    assert namespace["shapes"].w.shape == (201, 4)
    assert namespace["r"]["shooting"].inplane.omega_rad_s.shape == (6,)
    check = namespace["check"]
    assert [m.verdict for m in check.modes] == ["converges to a wrong limit"] * 4
    assert all(abs(m.bias_relative - 0.01) < 1e-5 for m in check.modes)
    namespace["plt"].close("all")
