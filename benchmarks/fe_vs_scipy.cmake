# SPDX-License-Identifier: MIT
# fe against SciPy's eigsh on the same matrices (issues 8 and 17): a plain executable, built with
# the tests or the benchmarks. Its ctest runs it at tiny sizes only, to keep it working (no timing
# is asserted; without SciPy the SciPy columns read -1).
add_executable(catena_fe_vs_scipy ${CMAKE_CURRENT_LIST_DIR}/fe_vs_scipy.cpp)
target_include_directories(catena_fe_vs_scipy PRIVATE ${PROJECT_SOURCE_DIR}/src)
target_compile_definitions(catena_fe_vs_scipy PRIVATE CATENA_BENCHMARK_DIR="${CMAKE_CURRENT_LIST_DIR}")
target_link_libraries(catena_fe_vs_scipy PRIVATE catena::catena fmt::fmt)
catena_set_warnings(catena_fe_vs_scipy)
if(CATENA_BUILD_TESTS)
  add_test(NAME fe_vs_scipy_tiny
           COMMAND catena_fe_vs_scipy --tiny --work ${PROJECT_BINARY_DIR}/fe-vs-scipy-tiny
                   --results ${PROJECT_BINARY_DIR}/fe-vs-scipy-tiny/table.txt)
  set_tests_properties(fe_vs_scipy_tiny PROPERTIES TIMEOUT 300)
  # A mistyped option exits 2 with the reason before anything runs (it once ran the whole
  # benchmark and replaced the committed table); --help lists the options and exits 0.
  add_test(NAME fe_vs_scipy_rejects_unknown_option
           COMMAND sh -c "\"$0\" --repeat 3 >/dev/null 2>err.txt; s=$?; grep -q \"unknown option '--repeat'\" err.txt && test $s -eq 2"
                   $<TARGET_FILE:catena_fe_vs_scipy>
           WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
  add_test(NAME fe_vs_scipy_help
           COMMAND sh -c "\"$0\" --help | grep -q -- '--max-elements N'" $<TARGET_FILE:catena_fe_vs_scipy>)
endif()
# The cost of 1, 6 and 20 modes per plane for each solver (issue 17; benchmarks/modes_cost.py),
# kept working at one mode on one scene (no timing asserted).
if(CATENA_BUILD_TESTS)
  find_package(Python3 COMPONENTS Interpreter)
  if(Python3_Interpreter_FOUND)
    add_test(NAME modes_cost_tiny
             COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/modes_cost.py --tiny
                     --catena $<TARGET_FILE:catena_cli> --out ${PROJECT_BINARY_DIR}/modes-cost-tiny.txt)
    set_tests_properties(modes_cost_tiny PROPERTIES TIMEOUT 300)
  endif()
endif()
