# SPDX-License-Identifier: MIT
# python/CMakeLists.txt as a project of its own: the extension catena._catena only, as
# `pip install ./python` builds it (python/setup.py; docs/reference/python.md, "Installing with pip").
#
# The library comes from, in this order:
#   1. an installed catena of the repository's version, found by find_package(catena CONFIG) through
#      CMAKE_PREFIX_PATH, catena_DIR or catena_ROOT: only the extension is compiled (a minute or two);
#   2. otherwise the repository around this folder (python/..), added as a subdirectory with its
#      tests and Python module off: the library is compiled too (~15 minutes on 2 cores).
# CATENA_PYTHON_FROM_SOURCES=ON skips 1. CATENA_SOURCE_VERSION: the repository's version (python/CMakeLists.txt
# reads it from python/../CMakeLists.txt).

if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()
option(CATENA_PYTHON_FROM_SOURCES "Build the library from python/.. even when an installed catena is found" OFF)
set(CATENA_BUILD_TESTS OFF)

if(NOT CATENA_PYTHON_FROM_SOURCES)
  find_package(catena ${CATENA_SOURCE_VERSION} CONFIG)
endif()
if(catena_FOUND)
  message(STATUS "Python module: against the installed catena ${catena_VERSION} (${catena_DIR})")
else()
  get_filename_component(catena_python_repository ${CMAKE_CURRENT_LIST_DIR}/../.. ABSOLUTE)
  message(STATUS "Python module: no installed catena ${CATENA_SOURCE_VERSION} found (CMAKE_PREFIX_PATH, "
                 "catena_DIR): building the library from ${catena_python_repository}")
  # The repository's own tests, tools and Python module (this file's includer) stay off.
  set(CATENA_BUILD_TESTS OFF CACHE BOOL "Build unit tests" FORCE)
  set(CATENA_BUILD_PYTHON OFF CACHE STRING "Build the Python module catena: AUTO, ON or OFF" FORCE)
  add_subdirectory(${catena_python_repository} catena EXCLUDE_FROM_ALL)
endif()
# Building the module is the point of this project: missing Python pieces are an error.
set(CATENA_BUILD_PYTHON ON)
# The bindings format messages with fmt themselves; imported targets found in the repository's
# directory are not visible here.
find_package(fmt REQUIRED)
