# SPDX-License-Identifier: MIT
"""Builds the extension catena._catena with CMake when pip installs ./python (pyproject.toml holds
the metadata; docs/reference/python.md, "Installing with pip").

Where the library comes from, in this order:

- CATENA_BUILD_DIR=<a configured build tree of this repository>: its target catena_python is built
  there (usually already up to date) and its module is packaged; nothing else is compiled.
- otherwise python/CMakeLists.txt as a project of its own (python/cmake/standalone.cmake): against
  an installed catena that find_package finds (CMAKE_PREFIX_PATH or catena_DIR in the environment),
  else the library built from the repository around this folder.

CATENA_CMAKE_ARGS adds arguments to that configuration (e.g. "-DCATENA_PYTHON_FROM_SOURCES=ON");
CMAKE_BUILD_PARALLEL_LEVEL and CMAKE_CXX_COMPILER_LAUNCHER (e.g. ccache) are CMake's own.
"""

import os
import pathlib
import re
import shlex
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = pathlib.Path(__file__).resolve().parent
REPOSITORY = HERE.parent


def repository_version() -> str:
    """The version in the repository's `project(catena VERSION x.y.z)`."""
    text = (REPOSITORY / "CMakeLists.txt").read_text()
    match = re.search(r"^project\(catena VERSION ([0-9]+\.[0-9]+\.[0-9]+)", text, re.MULTILINE)
    if not match:
        raise RuntimeError(f"no `project(catena VERSION x.y.z)` in {REPOSITORY / 'CMakeLists.txt'}")
    return match.group(1)


def run(command: list[str]) -> None:
    print("catena setup.py:", shlex.join(command), flush=True)
    subprocess.run(command, check=True)


class CMakeBuild(build_ext):
    """build_ext for the one extension: CMake builds it, this copies it where setuptools wants it."""

    def build_extension(self, ext: Extension) -> None:
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        build_dir = os.environ.get("CATENA_BUILD_DIR")
        built = self.from_build_tree(pathlib.Path(build_dir)) if build_dir else self.standalone()
        target.parent.mkdir(parents=True, exist_ok=True)
        self.copy_file(str(built), str(target))

    @staticmethod
    def module_in(folder: pathlib.Path) -> pathlib.Path:
        # The interpreter that runs pip must be the one the module is built for.
        module = folder / ("_catena" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not module.is_file():
            raise RuntimeError(f"{module} was not built (a module for another Python? this is "
                               f"{sys.executable}, Python {sysconfig.get_python_version()})")
        return module

    def from_build_tree(self, build_dir: pathlib.Path) -> pathlib.Path:
        if not (build_dir / "CMakeCache.txt").is_file():
            raise RuntimeError(f"CATENA_BUILD_DIR={build_dir}: not a configured CMake build tree")
        run(["cmake", "--build", str(build_dir), "--target", "catena_python"])
        return self.module_in(build_dir / "python" / "catena")

    def standalone(self) -> pathlib.Path:
        build_temp = pathlib.Path(self.build_temp).resolve() / "cmake"
        output = build_temp / "module"
        configure = ["cmake", "-S", str(HERE), "-B", str(build_temp), "-DCMAKE_BUILD_TYPE=Release",
                     f"-DPython3_EXECUTABLE={sys.executable}", f"-DCATENA_PYTHON_PACKAGE_DIR={output}"]
        if os.environ.get("catena_DIR"):
            configure.append(f"-Dcatena_DIR={os.environ['catena_DIR']}")
        configure += shlex.split(os.environ.get("CATENA_CMAKE_ARGS", ""))
        run(configure)
        parallel = [] if os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") else ["--parallel", str(os.cpu_count() or 1)]
        run(["cmake", "--build", str(build_temp), "--target", "catena_python"] + parallel)
        return self.module_in(output)


setup(
    version=repository_version(),
    packages=["catena"],
    package_data={"catena": ["py.typed", "*.pyi"]},  # PEP 561: the stubs and their marker
    ext_modules=[Extension("catena._catena", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
)
