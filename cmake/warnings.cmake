# SPDX-License-Identifier: MIT
# Warnings as the issues ask: -Wall -Wextra -Wpedantic -Wshadow, on our targets only.
# -Wno-restrict: GCC 12 reports a false -Wrestrict inside std::string assignment at -O2/-O3
# (GCC bug 105651); it points at libstdc++, not at our code.
# -Wno-array-bounds when compiling for AVX (cmake/instruction_set.cmake): GCC 12 and 13 report a
# 32-byte packet load from a 2-vector inside Eigen's vectorised assignment loops, in the branch
# that runs only for at least four elements (GCC bug 106247, Eigen issue 2506); it points at
# avxintrin.h through Eigen, not at our code.
function(catena_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                         $<$<AND:$<CXX_COMPILER_ID:GNU>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,13>>:-Wno-restrict>)
  if(CATENA_MARCH AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-array-bounds)
  endif()
endfunction()
