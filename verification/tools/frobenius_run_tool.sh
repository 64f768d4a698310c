#!/bin/sh
# Compiles and runs one of the frobenius verification tools against the built library.
# Usage (repository root, after `cmake --build build --target catena`):
#   verification/tools/frobenius_run_tool.sh frobenius_gale_tables [args...]
set -e
name="$1"; shift
mkdir -p build/frobenius-tools
g++ -O2 -std=c++20 -Iinclude -Isrc -I/usr/include/eigen3 "verification/tools/${name}.cpp" build/libcatena.a -lfmt \
  -o "build/frobenius-tools/${name}"
"build/frobenius-tools/${name}" "$@"
