// SPDX-License-Identifier: MIT
// The scene picture's data (include/catena/io/scene_picture.hpp) for Result.plot(), which draws it
// with matplotlib (python/catena/_plot.py): the same panels as `catena plot` draws in SVG.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "catena/io/scene_picture.hpp"

namespace catena::python {

void bind_plot(py::module_& m) {
  m.def(
      "_scene_picture",
      [](const std::string& results_json, const std::vector<int>& modes, bool all_modes,
         double mode_scale) {
        ScenePictureOptions options;
        options.modes = modes;
        options.all_modes = all_modes;
        options.mode_scale = mode_scale;
        return scene_picture_data(results_json, "result", "", options);
      },
      py::arg("results_json"), py::arg("modes"), py::arg("all_modes"), py::arg("mode_scale"));
}

}  // namespace catena::python
