// SPDX-License-Identifier: MIT
#pragma once
// The pieces of the extension module catena._catena (docs/reference/python.md), one file per
// concept, and the conversions they share. Nothing here is called while the GIL is released: every
// function that solves copies its Python arguments into C++ values first, releases the GIL for the
// C++ work only, and converts the C++ result back after re-acquiring it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "catena/core/types.hpp"

namespace catena::python {

namespace py = pybind11;

void bind_errors(py::module_& module);
void bind_line(py::module_& module);
void bind_model(py::module_& module);
void bind_statics(py::module_& module);
void bind_results(py::module_& module);
void bind_motion(py::module_& module);
void bind_dynamic_tension(py::module_& module);
void bind_solvers(py::module_& module);
void bind_scene(py::module_& module);
void bind_external_check(py::module_& module);
void bind_tension_check(py::module_& module);
void bind_timeseries_check(py::module_& module);
void bind_synthetic_output(py::module_& module);

/// Marks `array` read-only: result arrays are copies, and writing into one would change nothing.
py::array read_only(py::array array);
/// A new read-only array owning a copy of `values`.
py::array_t<double> owned_array(const Vector& values);
/// A new read-only array owning a copy of `values`.
py::array_t<double> owned_array(const std::vector<double>& values);

/// The C++ structs mark a missing value (no error estimate, not counted, not asked) with -1, a
/// number a Python caller could compare as if it were one (`estimate < tol` passes). Python gets
/// None for a missing scalar and NaN in an array (docs/reference/python.md, "Missing values").
template <class T>
std::optional<T> unless_missing(T value) {
  if (value < T(0)) return std::nullopt;
  return value;
}
/// `value`, or NaN when it is missing (negative).
inline double nan_if_missing(double value) {
  return value < 0.0 ? std::numeric_limits<double>::quiet_NaN() : value;
}

}  // namespace catena::python
