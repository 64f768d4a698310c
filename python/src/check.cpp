// SPDX-License-Identifier: MIT
// `catena check` from Python (docs/reference/python.md, "Comparing another code's frequencies"):
// the other code's results are read by the library's reader (a file, or JSON text that
// python/catena/_check_results.py builds from rows or columns), and compared by the library's
// check_scene, the call `catena check` makes; nothing of the comparison is done here. The GIL is
// released while reading and while the reference is solved.
#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "catena/core/error.hpp"
#include "catena/io/check_report.hpp"
#include "catena/io/external_results_reader.hpp"
#include "catena/io/file_access.hpp"
#include "catena/verification/scene_check.hpp"

namespace catena::python {
namespace {

constexpr double kRadPerSecondToHz = 1.0 / (2.0 * kPi);

/// The comparison with where it came from (for to_json, which must equal `catena check --json`).
struct CheckOutcome {
  SceneCheck checked;
  CheckSources sources;

  const ExternalCheck& check() const {
    if (!checked.check) throw std::runtime_error("no comparison was made: " + checked.error);
    return *checked.check;
  }
};

// The CLI's rule for --rtol, named as the Python argument.
ExternalCheckOptions check_options(double rtol) {
  if (!(rtol > 0.0 && rtol < 1.0))
    throw InvalidInput(fmt::format("rtol = {}: must be in (0, 1)", rtol));
  ExternalCheckOptions options;
  options.rtol = rtol;
  return options;
}

CheckOutcome check_released(const std::vector<ExternalMode>& results,
                            const Scene& scene,
                            double rtol,
                            CheckSources sources) {
  const ExternalCheckOptions options = check_options(rtol);
  sources.scene_name = scene.name;
  sources.scene_file = path_text(scene.file);
  const py::gil_scoped_release release;
  return {check_scene(results, scene, options), std::move(sources)};
}

CheckOutcome check_file(const std::filesystem::path& results,
                        const std::filesystem::path& shapes,
                        const Scene& scene,
                        double rtol) {
  check_options(rtol);
  std::vector<ExternalMode> modes;
  {
    const py::gil_scoped_release release;
    modes = read_external_results(results, shapes);
  }
  return check_released(modes, scene, rtol,
                        {"", "", path_text(results), shapes.empty() ? "" : path_text(shapes)});
}

CheckOutcome check_json_text(const std::string& text,
                             const std::string& origin,
                             const Scene& scene,
                             double rtol) {
  check_options(rtol);
  std::vector<ExternalMode> modes;
  {
    const py::gil_scoped_release release;
    modes = parse_external_results_json(text, origin);
  }
  return check_released(modes, scene, rtol, {"", "", origin, ""});
}

py::object optional_hz(const std::optional<double>& omega_rad_s) {
  return omega_rad_s ? py::cast(*omega_rad_s * kRadPerSecondToHz) : py::none();
}

void bind_reference(py::module_& module) {
  using R = CertifiedReference;
  py::class_<R>(module, "CertifiedReference",
                "Catena's reference for one plane: which solver, why, its modes.")
      .def_property_readonly("plane", [](const R& r) { return std::string(to_string(r.plane)); })
      .def_readonly("solver", &R::solver, "'shooting' or 'fe'")
      .def_readonly("reason", &R::reason, "why this solver, with what each exact solver reported")
      .def_property_readonly(
          "shooting_vs_fe_relative",
          [](const R& r) { return unless_missing(r.cross_check_relative); },
          "largest relative difference of shooting and fe over the modes (None: only one "
          "converged)")
      .def_property_readonly(
          "omega_rad_s",
          [](const R& r) {
            std::vector<double> values;
            for (const auto& m : r.modes) values.push_back(m.omega_rad_s);
            return owned_array(values);
          },
          "the reference modes, lowest first")
      .def_property_readonly("frequency_hz",
                             [](const R& r) {
                               std::vector<double> values;
                               for (const auto& m : r.modes)
                                 values.push_back(m.omega_rad_s * kRadPerSecondToHz);
                               return owned_array(values);
                             })
      .def_property_readonly(
          "relative_error_estimate",
          [](const R& r) {
            std::vector<double> values;
            for (const auto& m : r.modes)
              values.push_back(nan_if_missing(m.relative_error_estimate));
            return owned_array(values);
          },
          "the solver's own estimate of each mode [-], NaN for a mode without one")
      .def("__repr__", [](const R& r) {
        return fmt::format("CertifiedReference({}, {}, {} modes)", to_string(r.plane), r.solver,
                           r.modes.size());
      });
}

void bind_study(py::module_& module) {
  using S = ConvergenceStudy;
  py::class_<S>(
      module, "ConvergenceStudy",
      "The convergence study of one mode (three or more resolutions; docs/how-to/check.md).")
      .def_readonly("trustworthy", &S::trustworthy,
                    "monotone, order in [0.5, 10], stable; or at rounding level")
      .def_readonly("note", &S::note, "why it is not trustworthy, or what it rests on")
      .def_readonly("observed_order", &S::observed_order,
                    "from the finest three resolutions, or None")
      .def_readonly("coarser_order", &S::coarser_order, "from the three before the finest, or None")
      .def_readonly("limit_omega_rad_s", &S::limit_omega_rad_s,
                    "Richardson-extrapolated limit, or None")
      .def_property_readonly("limit_frequency_hz",
                             [](const S& s) { return optional_hz(s.limit_omega_rad_s); })
      .def_readonly("limit_uncertainty_rad_s", &S::limit_uncertainty_rad_s)
      .def_readonly("bias_relative", &S::bias_relative, "(limit - Catena) / Catena, or None");
}

void bind_resolution(py::module_& module) {
  using R = ResolutionComparison;
  py::class_<R>(module, "ResolutionComparison", "One resolution of one mode of the other code.")
      .def_readonly("resolution", &R::resolution, "the other code's mesh count, or None")
      .def_readonly("omega_rad_s", &R::omega_rad_s, "the other code's value")
      .def_property_readonly("frequency_hz",
                             [](const R& r) { return r.omega_rad_s * kRadPerSecondToHz; })
      .def_readonly("relative_error", &R::relative_error, "(other - Catena) / Catena")
      .def_readonly("mac", &R::mac, "MAC against Catena's shape, None without a shape")
      .def_readonly("tension_relative", &R::tension_relative,
                    "tension difference, None without tensions");
}

// The finest resolution's value of `field`, the quantities a one-line summary of a mode shows.
template <class T>
T finest(const ModeComparison& mode, T ResolutionComparison::*field) {
  if (mode.resolutions.empty()) throw std::logic_error("a compared mode without results");
  return mode.resolutions.back().*field;
}

template <class T>
py::object from_study(const ModeComparison& mode, std::optional<T> ConvergenceStudy::*field) {
  if (!mode.study || !(*mode.study.*field)) return py::none();
  return py::cast(*(*mode.study.*field));
}

void bind_mode_comparison(py::module_& module) {
  using M = ModeComparison;
  using R = ResolutionComparison;
  py::class_<M>(
      module, "ModeComparison",
      "One mode of the other code against Catena's reference. The scalar attributes are the finest "
      "resolution's; every resolution is in `resolutions` (coarsest first).")
      .def_property_readonly("plane", [](const M& m) { return std::string(to_string(m.plane)); })
      .def_readonly("mode", &M::mode, "the other code's mode number")
      .def_readonly("reference_index", &M::reference_index,
                    "Catena's mode it was paired with (0: unpaired)")
      .def_readonly("pairing", &M::pairing,
                    "'frequency' or 'MAC ...', with a note when the numbers differ")
      .def_property_readonly(
          "omega_rad_s", [](const M& m) { return finest(m, &R::omega_rad_s); }, "the other value")
      .def_property_readonly(
          "frequency_hz", [](const M& m) { return finest(m, &R::omega_rad_s) * kRadPerSecondToHz; })
      .def_property_readonly("resolution", [](const M& m) { return finest(m, &R::resolution); })
      .def_readonly("reference_omega_rad_s", &M::reference_omega_rad_s, "Catena's value")
      .def_property_readonly("reference_frequency_hz",
                             [](const M& m) { return m.reference_omega_rad_s * kRadPerSecondToHz; })
      .def_property_readonly(
          "reference_relative_estimate",
          [](const M& m) { return unless_missing(m.reference_relative_estimate); },
          "Catena's own estimate of its value [-], None when none")
      .def_property_readonly(
          "relative_error", [](const M& m) { return finest(m, &R::relative_error); },
          "(other - Catena) / Catena")
      .def_property_readonly(
          "mac", [](const M& m) { return finest(m, &R::mac); }, "None without shapes")
      .def_property_readonly("tension_relative",
                             [](const M& m) { return finest(m, &R::tension_relative); })
      .def_readonly("resolutions", &M::resolutions, "list of ResolutionComparison, coarsest first")
      .def_readonly("study", &M::study, "ConvergenceStudy (three or more resolutions), else None")
      .def_property_readonly(
          "observed_order",
          [](const M& m) { return from_study(m, &ConvergenceStudy::observed_order); })
      .def_property_readonly(
          "limit_omega_rad_s",
          [](const M& m) { return from_study(m, &ConvergenceStudy::limit_omega_rad_s); },
          "Richardson-extrapolated limit, or None")
      .def_property_readonly(
          "limit_frequency_hz",
          [](const M& m) {
            return optional_hz(m.study ? m.study->limit_omega_rad_s : std::nullopt);
          })
      .def_property_readonly(
          "bias_relative",
          [](const M& m) { return from_study(m, &ConvergenceStudy::bias_relative); },
          "(limit - Catena) / Catena, or None")
      .def_property_readonly(
          "verdict", [](const M& m) { return to_string(m.verdict); },
          "'within tolerance', 'beyond tolerance', 'converged', 'converges, not yet within "
          "tolerance', 'converges to a wrong limit' or 'unpaired'")
      .def_property_readonly("failed", [](const M& m) { return is_failure(m.verdict); })
      .def("__repr__", [](const M& m) {
        return fmt::format("ModeComparison({} {}: {})", to_string(m.plane), m.mode,
                           to_string(m.verdict));
      });
}

void bind_outcome(py::module_& module) {
  using O = CheckOutcome;
  py::class_<O>(module, "ExternalCheck",
                "The `catena check` comparison (docs/how-to/check.md): the references used, and "
                "per mode of the other "
                "code its comparison and verdict. `error` is set (and there is nothing else) when "
                "no reference "
                "could be computed, the CLI's exit 3.")
      .def_property_readonly("error",
                             [](const O& o) {
                               return o.checked.check ? std::nullopt
                                                      : std::optional(o.checked.error);
                             })
      .def_property_readonly("rtol", [](const O& o) { return o.check().options.rtol; })
      .def_property_readonly(
          "references", [](const O& o) { return o.check().references; },
          "one CertifiedReference per plane the results use")
      .def_property_readonly(
          "modes", [](const O& o) { return o.check().modes; },
          "list of ModeComparison, in-plane first, by the other code's number")
      .def_property_readonly(
          "failed", [](const O& o) { return !o.checked.check || o.checked.check->any_failure(); },
          "True when a mode fails (the CLI's exit 1) or there is no comparison")
      .def_property_readonly("scene_name", [](const O& o) { return o.sources.scene_name; })
      .def(
          "to_json", [](const O& o) { return check_to_json(o.check(), o.sources); },
          "The document `catena check --json` writes (docs/how-to/check.md).")
      .def("__repr__", [](const O& o) {
        if (!o.checked.check) return "ExternalCheck(error: " + o.checked.error + ")";
        return fmt::format("ExternalCheck('{}', {} modes, {})", o.sources.scene_name,
                           o.checked.check->modes.size(),
                           o.checked.check->any_failure() ? "failed" : "passed");
      });
}

}  // namespace

void bind_external_check(py::module_& module) {
  bind_reference(module);
  bind_study(module);
  bind_resolution(module);
  bind_mode_comparison(module);
  bind_outcome(module);
  module.def("_check_file", &check_file, py::arg("results"), py::arg("shapes"), py::arg("scene"),
             py::arg("rtol"));
  module.def("_check_json", &check_json_text, py::arg("text"), py::arg("origin"), py::arg("scene"),
             py::arg("rtol"));
}

}  // namespace catena::python
