// SPDX-License-Identifier: MIT
// `catena check` on another code's dynamic tension from Python (docs/reference/python.md,
// "Comparing another code's dynamic tension"): the other code's stations are read by the library's
// reader (a CSV file, or a dict of columns turned into the same table in memory, so that every
// message is the CLI's), and compared by check_scene_tension, the call `catena check` makes;
// nothing of the comparison is done here. The GIL is released while reading and solving.
#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "catena/core/error.hpp"
#include "catena/io/external_tension_reader.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/tension_check_json.hpp"
#include "catena/verification/scene_tension_check.hpp"

namespace catena::python {
namespace {

// The origin named in messages for columns given in Python.
constexpr const char* kColumnsOrigin = "<columns>";

struct TensionOutcome {
  SceneTensionCheck checked;
  CheckSources sources;

  const TensionCheck& check() const {
    if (!checked.check) throw std::runtime_error("no comparison was made: " + checked.error);
    return *checked.check;
  }
};

// A cell as the CSV would hold it: numbers printed round-trip, None empty, anything else its text
// (which the reader then rejects, naming the row and the column).
std::string cell_text(const py::handle& value) {
  if (value.is_none()) return "";
  if (py::isinstance<py::bool_>(value)) return py::str(value);
  try {
    return fmt::format("{:.17g}", value.cast<double>());
  } catch (const py::cast_error&) {
    return py::str(value);
  }
}

CsvTable table_from_columns(const py::dict& columns) {
  CsvTable table;
  std::size_t rows = 0;
  for (const auto& [key, values] : columns) {
    const std::string name = py::str(key);
    const py::list cells(py::reinterpret_borrow<py::object>(values));
    if (!table.columns.empty() && cells.size() != rows) {
      throw InvalidInput(fmt::format("{}: column '{}' has {} values, column '{}' has {}",
                                     kColumnsOrigin, name, cells.size(), table.columns.front(),
                                     rows));
    }
    rows = cells.size();
    table.rows.resize(rows);
    for (std::size_t r = 0; r < rows; ++r) table.rows[r].push_back(cell_text(cells[r]));
    table.columns.push_back(name);
  }
  return table;
}

ExternalCheckOptions tension_options(double rtol) {
  if (!(rtol > 0.0 && rtol < 1.0))
    throw InvalidInput(fmt::format("rtol = {}: must be in (0, 1)", rtol));
  ExternalCheckOptions options;
  options.rtol = rtol;
  return options;
}

TensionOutcome check_released(const ExternalTension& tension, const Scene& scene, double rtol) {
  const ExternalCheckOptions options = tension_options(rtol);
  CheckSources sources{scene.name, path_text(scene.file), tension.origin, ""};
  const py::gil_scoped_release release;
  return {check_scene_tension(tension, scene, options), std::move(sources)};
}

TensionOutcome check_tension_file(const std::filesystem::path& path,
                                  const Scene& scene,
                                  double rtol) {
  tension_options(rtol);
  ExternalTension tension;
  {
    const py::gil_scoped_release release;
    tension = read_external_tension(path);
  }
  return check_released(tension, scene, rtol);
}

TensionOutcome check_tension_columns(const py::dict& columns, const Scene& scene, double rtol) {
  tension_options(rtol);
  return check_released(external_tension_from_table(table_from_columns(columns), kColumnsOrigin),
                        scene, rtol);
}

// One column of the finest stations as a numpy array.
template <class Field>
py::array_t<double> station_column(const TensionOutcome& o, Field field) {
  std::vector<double> values;
  for (const auto& station : o.check().stations) values.push_back(field(station));
  return owned_array(values);
}

py::dict station_dict(const TensionStationComparison& c) {
  py::dict out;
  out["s_m"] = c.s_m;
  out["other_n"] = c.other_n;
  out["catena_n"] = c.catena_n;
  out["difference_n"] = c.difference_n;
  out["allowed_n"] = c.allowed_n;
  out["within"] = c.within;
  return out;
}

py::list studies_of(const TensionOutcome& o) {
  py::list out;
  for (const auto& s : o.check().studies) {
    py::dict d;
    d["station"] = s.label;
    d["s_m"] = s.s_m;
    d["resolutions"] = owned_array(s.resolutions);
    d["values_n"] = owned_array(s.values_n);
    d["trustworthy"] = s.study.trustworthy;
    d["note"] = s.study.note;
    d["observed_order"] = s.study.observed_order;
    d["limit_n"] = s.study.limit_omega_rad_s;
    d["limit_uncertainty_n"] = s.study.limit_uncertainty_rad_s;
    d["bias_relative"] = s.study.bias_relative;
    d["verdict"] = to_string(s.verdict);
    out.append(d);
  }
  return out;
}

void bind_tension_outcome(py::module_& module) {
  using O = TensionOutcome;
  py::class_<O>(module, "TensionCheck",
                "`catena check` on another code's dynamic tension "
                "(docs/how-to/check-dynamic-tension.md). `error` is set (and there is nothing "
                "else) when Catena could not compute the reference, the CLI's exit 3.")
      .def_property_readonly("error",
                             [](const O& o) {
                               return o.checked.check ? std::nullopt
                                                      : std::optional(o.checked.error);
                             })
      .def_property_readonly(
          "failed", [](const O& o) { return !o.checked.check || o.checked.check->any_failure(); },
          "True when a station fails (the CLI's exit 1) or there is no comparison")
      .def_property_readonly("verdict", [](const O& o) { return to_string(o.check().verdict); })
      .def_property_readonly("quantity", [](const O& o) { return to_string(o.check().quantity); })
      .def_property_readonly("reference_solver",
                             [](const O& o) { return o.check().reference.solver; })
      .def_property_readonly("reference_reason",
                             [](const O& o) { return o.check().reference.reason; })
      .def_property_readonly(
          "s_m", [](const O& o) { return station_column(o, [](const auto& c) { return c.s_m; }); })
      .def_property_readonly(
          "other_n",
          [](const O& o) { return station_column(o, [](const auto& c) { return c.other_n; }); })
      .def_property_readonly(
          "catena_n",
          [](const O& o) { return station_column(o, [](const auto& c) { return c.catena_n; }); })
      .def_property_readonly("difference_n",
                             [](const O& o) {
                               return station_column(o,
                                                     [](const auto& c) { return c.difference_n; });
                             })
      .def_property_readonly(
          "allowed_n",
          [](const O& o) { return station_column(o, [](const auto& c) { return c.allowed_n; }); })
      .def_property_readonly(
          "fairlead",
          [](const O& o) -> py::object {
            const auto& f = o.check().fairlead;
            return f ? py::object(station_dict(*f)) : py::none();
          },
          "the station at s = L as a dict, or None when the other code does not give it")
      .def_property_readonly("studies", &studies_of,
                             "one dict per station every resolution gives (three or more)")
      .def(
          "to_json", [](const O& o) { return tension_check_to_json(o.check(), o.sources); },
          "The document `catena check --json` writes for a tension file.")
      .def("__repr__", [](const O& o) {
        if (!o.checked.check) return "TensionCheck(error: " + o.checked.error + ")";
        return fmt::format("TensionCheck('{}', {} stations, {})", o.sources.scene_name,
                           o.checked.check->stations.size(), to_string(o.checked.check->verdict));
      });
}

}  // namespace

void bind_tension_check(py::module_& module) {
  bind_tension_outcome(module);
  module.def("_check_tension_file", &check_tension_file, py::arg("results"), py::arg("scene"),
             py::arg("rtol"));
  module.def("_check_tension_columns", &check_tension_columns, py::arg("columns"), py::arg("scene"),
             py::arg("rtol"));
}

}  // namespace catena::python
