#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian packages Catena needs to build, test, benchmark and draw its report.
# Idempotent: packages already present are not touched; `apt-get update` runs once, only when
# something is missing. Needs root (or sudo) on a Debian 12 machine.
set -euo pipefail

packages=(
  build-essential cmake make git pkg-config
  libeigen3-dev libspectra-dev libsundials-dev libboost-dev
  libtoml11-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-matplotlib python3-scipy
  python3-dev pybind11-dev python3-numpy python3-pytest   # the Python module and its tests (docs/reference/python.md)
  python3-venv        # pip install ./python into a virtual environment (test python_pip_install)
  python3-pip         # pip itself, in that environment
  python3-setuptools  # the build backend of python/pyproject.toml (pip --no-build-isolation)
  python3-wheel       # setuptools builds the wheel pip installs
  python3-mypy        # the stubs and annotations checked by mypy and stubtest (python/tests/test_typing.py)
  python3-distributed # catena sweep's Dask (docs/how-to/sweep.md); Parquet output would need pyarrow or
  python3-pandas      #   fastparquet, which Debian 12 does not package: sweeps write CSV only
  universal-ctags     # the function-length check (scripts/check_function_length.py)
  clang-format        # the formatting check (scripts/check_format.py)
  chromium            # the HTML report is checked in headless Chromium (test skipped without it)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=""
if [ "$(id -u)" -ne 0 ]; then sudo_cmd="sudo"; fi
echo "setup: installing ${missing[*]}"
$sudo_cmd apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
