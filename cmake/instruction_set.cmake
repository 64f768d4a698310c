# SPDX-License-Identifier: MIT
# The instruction set everything is compiled for (docs/how-to/build.md; docs/explanation/methods/fe.md, "Cost").
# Without a -march flag GCC emits SSE2 only: Eigen's dense products and our Gram-Schmidt loops then
# work on two doubles at a time without fused multiply-add. With AVX2 and FMA (x86-64-v3: every
# x86-64 processor since about 2015) fe's solve at N = 1000 runs about 1.5 times faster.
#
# CATENA_ARCH: OFF, the default, keeps the compiler's default (baseline x86-64 on Debian), so that
# an installed binary runs on any x86-64 processor; AUTO uses x86-64-v3 when the compiler accepts
# it and the build machine runs it (the binaries then need such a processor: SIGILL elsewhere);
# any other value is passed to -march (e.g. native). The cost of the portable default is measured
# in benchmarks/README.md. The flag applies to every target of the build: Eigen's alignment
# of fixed-size types depends on it, so all translation units must agree.
#
# Results depend on the instruction set in the last bits (fused multiply-add rounds once where a
# multiply then an add rounds twice); build_info records the choice and reports print it.
set(CATENA_ARCH OFF CACHE STRING "Instruction set: OFF (portable, the default), AUTO (x86-64-v3 when available), or a -march value")

function(catena_instruction_set out)
  if(CATENA_ARCH STREQUAL "OFF")
    set(${out} "" PARENT_SCOPE)
    return()
  endif()
  if(NOT CATENA_ARCH STREQUAL "AUTO")
    set(${out} "${CATENA_ARCH}" PARENT_SCOPE)
    return()
  endif()
  include(CheckCXXSourceRuns)
  set(CMAKE_REQUIRED_FLAGS "-march=x86-64-v3")
  set(CMAKE_REQUIRED_QUIET ON)
  check_cxx_source_runs([=[
    int main() {
      __builtin_cpu_init();
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? 0 : 1;
    }]=] CATENA_HOST_RUNS_X86_64_V3)
  if(CATENA_HOST_RUNS_X86_64_V3)
    set(${out} "x86-64-v3" PARENT_SCOPE)
  else()
    set(${out} "" PARENT_SCOPE)
  endif()
endfunction()

catena_instruction_set(CATENA_MARCH)
if(CATENA_MARCH)
  add_compile_options(-march=${CATENA_MARCH})
  set(CATENA_INSTRUCTION_SET "-march=${CATENA_MARCH}")
else()
  set(CATENA_INSTRUCTION_SET "compiler default")
endif()
message(STATUS "catena: instruction set ${CATENA_INSTRUCTION_SET} (CATENA_ARCH=${CATENA_ARCH})")
