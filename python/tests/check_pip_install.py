# SPDX-License-Identifier: MIT
"""ctest python_pip_install: `pip install ./python` into a fresh virtual environment, offline
(--no-index, --no-build-isolation: Debian's setuptools and wheel, no package index), then, from
that environment and outside the source tree, an import, the typing files, and one solve.

The library the install builds against (python/setup.py):
- when this build tree installs catena's CMake package (catenaConfig.cmake), the build is installed
  (`cmake --install`) into a temporary prefix and found there by find_package, the way a user with
  an installed catena builds (only the extension is compiled, in python/build/);
- otherwise (before the library is installable) the build tree's own module is packaged
  (CATENA_BUILD_DIR).
The other way, the library compiled from the sources, takes ~15 minutes on 2 cores and is not run
here. Exit 77 (ctest: skipped) only when venv or pip is missing.

Usage: check_pip_install.py --source-dir <repo>/python --build-dir <build>
"""

import argparse
import os
import pathlib
import subprocess
import sys
import tempfile
import time

SKIP = 77

# Run by the installed package, from a folder outside the sources.
SMOKE_TEST = r"""
import math, pathlib, sys
import catena
package = pathlib.Path(catena.__file__).parent
assert package.is_relative_to(sys.prefix), f"imported {package}, not the environment's"
for name in ("py.typed", "_catena.pyi"):
    assert (package / name).is_file(), f"{name} is not installed"
problem = catena.Problem(catena.Cable(length_m=1000.0, weight_n_per_m=1000.0, mass_kg_per_m=120.0,
                                      axial_stiffness_n=5e8, added_mass_kg_per_m=80.0), b_m=(900.0, 300.0))
out = catena.solve_fe(problem, catena.Request(inplane_modes=2), elements=100)
assert out.summary.status == "converged", out.summary.full_report()
assert all(math.isfinite(w) and w > 0 for w in out.inplane.omega_rad_s)
print("catena", catena.__version__, "from", package, "omega_rad_s", out.inplane.omega_rad_s.tolist())
"""


def installs_cmake_package(build_dir: pathlib.Path) -> bool:
    """Whether `cmake --install` of this build tree writes catena's CMake package (either of the
    names find_package looks for)."""
    names = ("catenaConfig.cmake", "catena-config.cmake")
    return any(name in path.read_text(errors="replace")
               for path in build_dir.rglob("cmake_install.cmake") for name in names)


def run(command: list[str], **kwargs: object) -> None:
    print("+", " ".join(str(c) for c in command), flush=True)
    start = time.monotonic()
    subprocess.run(command, check=True, **kwargs)  # type: ignore[call-overload]
    print(f"  ({time.monotonic() - start:.1f} s)", flush=True)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source-dir", type=pathlib.Path, required=True, help="the folder python/")
    parser.add_argument("--build-dir", type=pathlib.Path, required=True, help="the CMake build tree")
    args = parser.parse_args()

    try:
        import ensurepip  # noqa: F401  (Debian: python3-venv)
        import venv  # noqa: F401
    except ImportError as error:
        print(f"SKIP: {error} (Debian: python3-venv, python3-pip)")
        return SKIP

    with tempfile.TemporaryDirectory(prefix="catena-pip-") as scratch:
        scratch_dir = pathlib.Path(scratch)
        env_dir = scratch_dir / "env"
        try:
            run([sys.executable, "-m", "venv", "--system-site-packages", str(env_dir)])
        except subprocess.CalledProcessError:
            print("SKIP: python3 -m venv failed (Debian: python3-venv)")
            return SKIP
        python = env_dir / "bin" / "python3"
        if subprocess.run([python, "-m", "pip", "--version"], capture_output=True).returncode != 0:
            print("SKIP: no pip in the virtual environment (Debian: python3-pip)")
            return SKIP

        environment = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "CATENA_BUILD_DIR")}
        environment["PIP_NO_INDEX"] = "1"
        environment["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
        if installs_cmake_package(args.build_dir):
            prefix = scratch_dir / "prefix"
            run(["cmake", "--install", str(args.build_dir), "--prefix", str(prefix)])
            environment["CMAKE_PREFIX_PATH"] = str(prefix)
            environment["CATENA_CMAKE_ARGS"] = "-DCATENA_PYTHON_FROM_SOURCES=OFF"
            print("library: installed from the build tree into", prefix, "(find_package)")
        else:
            environment["CATENA_BUILD_DIR"] = str(args.build_dir.resolve())
            print("library: this build tree installs no catenaConfig.cmake; packaging its module "
                  "(CATENA_BUILD_DIR)")
        run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index",
             str(args.source_dir.resolve())], env=environment, cwd=scratch_dir)
        run([python, "-c", SMOKE_TEST], env=environment, cwd=scratch_dir)
    print("python_pip_install: passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
