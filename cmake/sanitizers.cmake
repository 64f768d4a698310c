# SPDX-License-Identifier: MIT
# CATENA_SANITIZE=ON: AddressSanitizer + UndefinedBehaviorSanitizer on everything this project
# compiles (library, CLI, tests, fuzz driver). Used by `make test-sanitize` (docs/contributing/testing.md).
#
# -fno-sanitize-recover=all makes the first report abort the process, so that a ctest or a fuzz
# iteration fails instead of printing a warning nobody reads. GCC's -fsanitize=undefined does not
# include float-cast-overflow (an out-of-range double -> int conversion, the class of the
# "modes = [1e20]" defect), so it is asked for explicitly (clang's -fsanitize=undefined has it; naming it again is harmless).
# Prebuilt libraries (SUNDIALS, fmt, GoogleTest) are not instrumented; header-only ones (Eigen,
# Spectra, toml11, nlohmann_json, Boost) are, through our translation units.
option(CATENA_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)

if(CATENA_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "CATENA_SANITIZE needs GCC or clang (found ${CMAKE_CXX_COMPILER_ID})")
  endif()
  set(CATENA_SANITIZER_FLAGS
      -fsanitize=address,undefined,float-cast-overflow
      -fno-sanitize-recover=all
      -fno-omit-frame-pointer)
  add_compile_options(${CATENA_SANITIZER_FLAGS})
  add_link_options(${CATENA_SANITIZER_FLAGS})
  message(STATUS "catena: AddressSanitizer + UndefinedBehaviorSanitizer (with float-cast-overflow) ON")
endif()
