// SPDX-License-Identifier: MIT
// The extension module catena._catena; the package python/catena/__init__.py re-exports it with
// the conveniences written in Python (docs/reference/python.md).
#include <algorithm>

#include "bindings.hpp"
#include "catena/core/version.hpp"

namespace catena::python {

py::array read_only(py::array array) {
  array.attr("setflags")(py::arg("write") = false);
  return array;
}

py::array_t<double> owned_array(const Vector& values) {
  py::array_t<double> array(values.size());
  std::copy(values.data(), values.data() + values.size(), array.mutable_data());
  read_only(array);
  return array;
}

py::array_t<double> owned_array(const std::vector<double>& values) {
  py::array_t<double> array(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  read_only(array);
  return array;
}

}  // namespace catena::python

PYBIND11_MODULE(_catena, module) {
  using namespace catena::python;
  module.doc() =
      "Catena's library: linear cable dynamics by five independent solvers "
      "(docs/reference/python.md).";
  module.attr("__version__") = catena::version();
  bind_errors(module);
  bind_line(module);
  bind_motion(module);
  bind_model(module);
  bind_statics(module);
  bind_results(module);
  bind_dynamic_tension(module);
  bind_solvers(module);
  bind_scene(module);
  bind_external_check(module);
  bind_tension_check(module);
  bind_timeseries_check(module);
  bind_synthetic_output(module);
}
