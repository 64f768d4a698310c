// SPDX-License-Identifier: MIT
// `catena check` on a free decay from Python (docs/reference/python.md, "Checking a free decay"):
// files are read by the library's reader and arrays become the same TimeSeries in memory, so every
// message is the CLI's; the comparison is check_time_series_runs, the call `catena check` makes.
// The GIL is released while reading, identifying and solving.
#include "catena/verification/timeseries_check.hpp"

#include <fmt/format.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "catena/core/error.hpp"
#include "catena/io/file_access.hpp"
#include "catena/io/timeseries_check_json.hpp"
#include "catena/io/timeseries_reader.hpp"

namespace catena::python {
namespace {

// The origin named in messages for samples given in Python.
constexpr const char* kArraysOrigin = "<arrays>";

struct TimeSeriesOutcome {
  TimeSeriesCheck check;
  TimeSeriesSources sources;
};

TimeSeriesCheckOptions options_of(const std::vector<std::string>& channels,
                                  std::optional<double> window_start_s,
                                  std::optional<double> window_end_s,
                                  const std::string& plane,
                                  const std::vector<double>& resolutions,
                                  double min_frequency_hz,
                                  double max_frequency_hz) {
  TimeSeriesCheckOptions options;
  options.channels = channels;
  options.window_start_s = window_start_s;
  options.window_end_s = window_end_s;
  if (plane == "in-plane") {
    options.plane = Plane::InPlane;
  } else if (plane == "out-of-plane") {
    options.plane = Plane::OutOfPlane;
  } else if (!plane.empty()) {
    throw InvalidInput(fmt::format("plane = '{}': must be 'in-plane' or 'out-of-plane'", plane));
  }
  options.resolutions = resolutions;
  options.min_frequency_hz = min_frequency_hz;
  options.max_frequency_hz = max_frequency_hz;
  options.validate();
  return options;
}

TimeSeriesOutcome run(const std::vector<TimeSeries>& runs,
                      const Scene& scene,
                      const TimeSeriesCheckOptions& options,
                      std::vector<std::string> files) {
  TimeSeriesOutcome outcome;
  outcome.sources = {scene.name, path_text(scene.file), std::move(files), options.channels};
  outcome.check = check_time_series_runs(scene, runs, options);
  return outcome;
}

TimeSeriesOutcome check_files(const std::vector<std::filesystem::path>& files,
                              const Scene& scene,
                              const std::vector<std::string>& channels,
                              std::optional<double> window_start_s,
                              std::optional<double> window_end_s,
                              const std::string& plane,
                              const std::vector<double>& resolutions,
                              double min_frequency_hz,
                              double max_frequency_hz) {
  const TimeSeriesCheckOptions options =
      options_of(channels, window_start_s, window_end_s, plane, resolutions, min_frequency_hz,
                 max_frequency_hz);
  const py::gil_scoped_release release;
  std::vector<TimeSeries> runs;
  std::vector<std::string> names;
  for (const auto& file : files) {
    runs.push_back(read_time_series(file));
    names.push_back(path_text(file));
  }
  return run(runs, scene, options, names);
}

TimeSeriesOutcome check_samples(const Vector& time_s,
                                const std::vector<std::string>& names,
                                const std::vector<Vector>& columns,
                                const Scene& scene,
                                const std::vector<std::string>& channels,
                                std::optional<double> window_start_s,
                                std::optional<double> window_end_s,
                                const std::string& plane,
                                double min_frequency_hz,
                                double max_frequency_hz) {
  const TimeSeriesCheckOptions options = options_of(channels, window_start_s, window_end_s, plane,
                                                    {}, min_frequency_hz, max_frequency_hz);
  const py::gil_scoped_release release;
  const TimeSeries series = time_series_from_samples(time_s, names, columns, kArraysOrigin);
  return run({series}, scene, options, {kArraysOrigin});
}

py::object optional_hz(const std::optional<double>& rad_s) {
  return rad_s ? py::float_(*rad_s / (2.0 * kPi)) : py::none();
}

py::dict study_dict(const TimeSeriesStudy& s) {
  py::dict d;
  d["resolutions"] = owned_array(s.resolutions);
  d["frequencies_hz"] = owned_array(s.frequencies_hz);
  d["frequency_uncertainties_hz"] = owned_array(s.frequency_uncertainties_hz);
  d["trustworthy"] = s.study.trustworthy;
  d["note"] = s.study.note;
  d["observed_order"] = s.study.observed_order;
  d["limit_frequency_hz"] = optional_hz(s.study.limit_omega_rad_s);
  d["bias_relative"] = s.study.bias_relative;
  d["verdict"] = s.verdict;
  return d;
}

void bind_mode(py::module_& module) {
  using M = TimeSeriesModeCheck;
  py::class_<M>(module, "TimeSeriesMode",
                "One identified mode compared with Catena's damped mode "
                "(docs/how-to/check-time-series.md). `mode` is Catena's number, None when "
                "unmatched; frequencies [Hz], damping ratios [-].")
      .def_readonly("plane", &M::plane)
      .def_property_readonly(
          "mode", [](const M& m) { return m.mode > 0 ? std::optional(m.mode) : std::nullopt; })
      .def_readonly("identified_frequency_hz", &M::identified_frequency_hz)
      .def_readonly("frequency_uncertainty_hz", &M::frequency_uncertainty_hz)
      .def_readonly("identified_damping_ratio", &M::identified_damping_ratio)
      .def_readonly("damping_ratio_uncertainty", &M::damping_ratio_uncertainty)
      .def_readonly("identified_decay_rate_1_s", &M::identified_decay_rate_1_s)
      .def_readonly("signal_to_noise", &M::signal_to_noise)
      .def_readonly("catena_frequency_hz", &M::catena_frequency_hz)
      .def_readonly("catena_damping_ratio", &M::catena_damping_ratio)
      .def_readonly("catena_frequency_error_hz", &M::catena_frequency_error_hz)
      .def_readonly("catena_damping_ratio_error", &M::catena_damping_ratio_error)
      .def_readonly("frequency_error_hz", &M::frequency_error_hz)
      .def_readonly("damping_ratio_error", &M::damping_ratio_error)
      .def_readonly("verdict", &M::verdict)
      .def_readonly("note", &M::note)
      .def_property_readonly(
          "study",
          [](const M& m) -> py::object {
            return m.study ? py::object(study_dict(*m.study)) : py::none();
          },
          "several runs: the convergence study as a dict (order, limit, bias, verdict), else None")
      .def("__repr__", [](const M& m) {
        return fmt::format("TimeSeriesMode({} {}, {:.8g} Hz, zeta {:.4g}: {})", m.plane,
                           m.mode > 0 ? std::to_string(m.mode) : "-", m.identified_frequency_hz,
                           m.identified_damping_ratio, m.verdict);
      });
}

void bind_outcome(py::module_& module) {
  using O = TimeSeriesOutcome;
  py::class_<O>(
      module, "TimeSeriesCheck",
      "`catena check` on a free decay (docs/how-to/check-time-series.md). `error` is set "
      "(and `modes` empty) when Catena could not compute its reference, the CLI's exit 3.")
      .def_property_readonly("modes", [](const O& o) { return o.check.modes; })
      .def_property_readonly(
          "not_present",
          [](const O& o) {
            py::list out;
            for (const auto& m : o.check.not_present) {
              py::dict d;
              d["plane"] = m.plane;
              d["mode"] = m.mode;
              d["catena_frequency_hz"] = m.catena_frequency_hz;
              d["catena_damping_ratio"] = m.catena_damping_ratio;
              out.append(d);
            }
            return out;
          },
          "Catena's modes below the highest matched one that the record does "
          "not show (dicts)")
      .def_property_readonly("notes", [](const O& o) { return o.check.notes; })
      .def_property_readonly(
          "window_s",
          [](const O& o) { return std::pair(o.check.window_start_s, o.check.window_end_s); })
      .def_property_readonly(
          "reference_solvers",
          [](const O& o) {
            py::dict out;
            for (const auto& p : o.check.planes) out[py::str(p.plane)] = p.reference_solver;
            return out;
          },
          "{plane: the exact solver that gave Catena's modes}")
      .def_property_readonly("error",
                             [](const O& o) {
                               return o.check.error.empty() ? std::nullopt
                                                            : std::optional(o.check.error);
                             })
      .def_property_readonly(
          "failed", [](const O& o) { return o.check.any_failure(); },
          "True when the CLI exits 1 (a mode disagrees or is unmatched, a "
          "study converges to a wrong limit, nothing was verified) or 3")
      .def(
          "to_json", [](const O& o) { return timeseries_check_to_json(o.check, o.sources); },
          "The document `catena check --json` writes for a time series.")
      .def("__repr__", [](const O& o) {
        if (!o.check.error.empty()) return "TimeSeriesCheck(error: " + o.check.error + ")";
        return fmt::format(
            "TimeSeriesCheck('{}', {} agree, {} disagree, {} not identifiable, "
            "{} unmatched)",
            o.sources.scene_name, o.check.agrees, o.check.disagrees, o.check.not_identifiable,
            o.check.unmatched);
      });
}

}  // namespace

void bind_timeseries_check(py::module_& module) {
  bind_mode(module);
  bind_outcome(module);
  module.def("_check_timeseries_files", &check_files, py::arg("files"), py::arg("scene"),
             py::arg("channels"), py::arg("window_start_s"), py::arg("window_end_s"),
             py::arg("plane"), py::arg("resolutions"), py::arg("min_frequency_hz"),
             py::arg("max_frequency_hz"));
  module.def("_check_timeseries_samples", &check_samples, py::arg("time_s"), py::arg("names"),
             py::arg("columns"), py::arg("scene"), py::arg("channels"), py::arg("window_start_s"),
             py::arg("window_end_s"), py::arg("plane"), py::arg("min_frequency_hz"),
             py::arg("max_frequency_hz"));
}

}  // namespace catena::python
