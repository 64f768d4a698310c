# SPDX-License-Identifier: MIT
# The install_consumer test (registered in tests/install/CMakeLists.txt), run as
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DSCENE=... -DGENERATOR=... -DCXX_COMPILER=...
#         -DBUILD_TYPE=... [-DLAUNCHER=...] -P install_consumer.cmake
# It installs the build tree into WORK_DIR/prefix as a user would (`cmake --install`), then checks
#   1. the installed headers include only installed headers (nothing from src/, nothing generated);
#   2. the version file accepts 0.2 and 0.2.0 and refuses 0.1, 0.3, 1.0 and 0.2.1 (SameMinorVersion);
#   3. a project outside the tree (tests/install/consumer/) finds the package in the prefix,
#      builds one program on catena::catena and one on catena::verification, and runs them: the
#      statics of the mooring line built in code (consumer/main.cpp) equal those of the same line
#      read from SCENE by the harness (consumer/read_scene.cpp) and those of the installed CLI, and
#      shooting's in-plane frequencies agree by both routes.
cmake_minimum_required(VERSION 3.21)
foreach(variable BUILD_DIR WORK_DIR SCENE GENERATOR CXX_COMPILER BUILD_TYPE)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "install_consumer.cmake: -D${variable}=... is required")
  endif()
endforeach()
set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer-build)
file(REMOVE_RECURSE ${WORK_DIR})

function(run_or_fail what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${output}\n${error}")
  endif()
  set(run_output "${output}" PARENT_SCOPE)
endfunction()

# The first line of `text` that starts with `prefix`.
function(line_starting_with out text prefix)
  string(REGEX MATCH "(^|\n)${prefix}[^\n]*" line "${text}")
  string(STRIP "${line}" line)
  if(NOT line)
    message(FATAL_ERROR "no line starting with '${prefix}' in:\n${text}")
  endif()
  set(${out} "${line}" PARENT_SCOPE)
endfunction()

# 0. Install.
run_or_fail("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# 1. Installed headers: every #include "..." names an installed header; nothing private installed.
file(GLOB_RECURSE headers RELATIVE ${prefix}/include ${prefix}/include/*)
list(LENGTH headers header_count)
if(header_count EQUAL 0)
  message(FATAL_ERROR "no header installed in ${prefix}/include")
endif()
foreach(header ${headers})
  if(NOT header MATCHES "^catena/" OR header MATCHES "/internal/|build_info|data_dirs")
    message(FATAL_ERROR "private or generated header installed: include/${header}")
  endif()
  file(STRINGS ${prefix}/include/${header} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line ${includes})
    string(REGEX REPLACE "^[^\"]*\"([^\"]+)\".*" "\\1" included "${line}")
    if(NOT EXISTS ${prefix}/include/${included})
      message(FATAL_ERROR "include/${header} includes \"${included}\", which is not installed")
    endif()
  endforeach()
endforeach()
message(STATUS "${header_count} headers installed, each including only installed headers")

# 2. Version compatibility, as find_package(catena <version>) asks it.
file(GLOB_RECURSE version_file ${prefix}/catenaConfigVersion.cmake)
if(NOT version_file)
  message(FATAL_ERROR "no catenaConfigVersion.cmake installed in ${prefix}")
endif()
foreach(request 0.2:TRUE 0.2.0:TRUE 0.1:FALSE 0.3:FALSE 1.0:FALSE 0.2.1:FALSE)
  string(REPLACE ":" ";" request "${request}")
  list(GET request 0 PACKAGE_FIND_VERSION)
  list(GET request 1 expected)
  string(REPLACE "." ";" parts "${PACKAGE_FIND_VERSION}.0")
  list(GET parts 0 PACKAGE_FIND_VERSION_MAJOR)
  list(GET parts 1 PACKAGE_FIND_VERSION_MINOR)
  list(GET parts 2 PACKAGE_FIND_VERSION_PATCH)
  unset(PACKAGE_VERSION_COMPATIBLE)
  unset(PACKAGE_VERSION_UNSUITABLE)
  set(CMAKE_SIZEOF_VOID_P 8)
  include(${version_file})
  if((expected AND NOT PACKAGE_VERSION_COMPATIBLE) OR (NOT expected AND PACKAGE_VERSION_COMPATIBLE))
    message(FATAL_ERROR "catena ${PACKAGE_VERSION} for a request of ${PACKAGE_FIND_VERSION}: "
                        "compatible = '${PACKAGE_VERSION_COMPATIBLE}', expected ${expected}")
  endif()
endforeach()
message(STATUS "catena ${PACKAGE_VERSION}: accepts 0.2, 0.2.0; refuses 0.1, 0.3, 1.0, 0.2.1")

# 3. The consumer project, against the prefix only.
set(configure_args -S ${CMAKE_CURRENT_LIST_DIR}/consumer -B ${consumer_build} -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
if(LAUNCHER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run_or_fail("configuring the consumer" ${CMAKE_COMMAND} ${configure_args})
string(FIND "${run_output}" "catena ${PACKAGE_VERSION} from ${prefix}/" found_at)
if(found_at EQUAL -1)
  message(FATAL_ERROR "the consumer did not find catena in ${prefix}:\n${run_output}")
endif()
run_or_fail("building the consumer" ${CMAKE_COMMAND} --build ${consumer_build})

run_or_fail("catena_solve_cable" ${consumer_build}/catena_solve_cable)
set(numerics "${run_output}")
run_or_fail("catena_read_scene" ${consumer_build}/catena_read_scene ${SCENE})
set(harness "${run_output}")
run_or_fail("the installed catena solve" ${prefix}/bin/catena solve ${SCENE})
set(cli "${run_output}")
message(STATUS "catena_solve_cable:\n${numerics}catena_read_scene:\n${harness}")

# The forces as each prints them (the CLI's statics line is laid out differently: catena solve
# leads with a short line, docs/reference/solve-output.md), to the same 10 digits.
function(statics_forces out line)
  string(REGEX MATCHALL "(H|T_A|T_B) = [^ ,]+ N" forces "${line}")
  set(${out} "${forces}" PARENT_SCOPE)
endfunction()
line_starting_with(statics_numerics "${numerics}" "statics: ")
line_starting_with(statics_harness "${harness}" "statics: ")
line_starting_with(statics_cli "${cli}" "  statics: ")
statics_forces(forces_numerics "${statics_numerics}")
list(LENGTH forces_numerics forces_count)
if(NOT forces_count EQUAL 3)
  message(FATAL_ERROR "catena_solve_cable's statics line lacks H, T_A or T_B: ${statics_numerics}")
endif()
foreach(other statics_harness statics_cli)
  statics_forces(forces_other "${${other}}")
  if(NOT forces_other STREQUAL forces_numerics)
    message(FATAL_ERROR "statics differ:\n  catena_solve_cable: ${statics_numerics}\n  ${other}: ${${other}}")
  endif()
endforeach()
line_starting_with(modes_numerics "${numerics}" "shooting in-plane")
line_starting_with(modes_harness "${harness}" "shooting in-plane")
if(NOT modes_numerics STREQUAL modes_harness OR NOT modes_numerics MATCHES "\\(converged\\)$")
  message(FATAL_ERROR "shooting's modes:\n  catena_solve_cable: ${modes_numerics}\n  catena_read_scene: ${modes_harness}")
endif()
if(NOT harness MATCHES "checks: [1-9][0-9]*, failed: 0")
  message(FATAL_ERROR "the scene's checks:\n${harness}")
endif()
message(STATUS "install_consumer: passed")
