// SPDX-License-Identifier: MIT
// The dynamic tension of a motion request (catena::DynamicTension, docs/explanation/
// dynamic-tension.md) as numpy arrays: the profiles along the line, the fairlead and anchor values,
// the linearised drag, the tension spectra and the fixed point's report. What does not apply to
// the motion (an amplitude of an irregular motion, a standard deviation of a regular one, spectra
// of a regular one) is None, not an empty array or -1 (docs/reference/python.md, "Missing values").
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "catena/solvers/modal_result.hpp"

namespace catena::python {
namespace {

// An array of the result, or None when the motion does not have it (empty).
py::object array_or_none(const Vector& values) {
  if (values.size() == 0) return py::none();
  return owned_array(values);
}

void bind_end(py::module_& module) {
  using E = DynamicTensionEnd;
  py::class_<E>(module, "DynamicTensionEnd",
                "The dynamic tension at the fairlead (end b) or the anchor (end a) beside the "
                "mean tension of the statics.")
      .def_readonly("s_m", &E::s_m, "unstretched arc length from end a [m]")
      .def_readonly("mean_n", &E::mean_n, "static (mean) tension [N]")
      .def_property_readonly(
          "amplitude_n", [](const E& e) { return unless_missing(e.amplitude_n); },
          "regular motion: tension amplitude |tau| [N]; None when irregular")
      .def_property_readonly(
          "phase_deg",
          [](const E& e) {
            return e.amplitude_n < 0.0 ? std::nullopt : std::optional(e.phase_deg);
          },
          "regular motion: phase of tau relative to the motion of end b [deg]; None when irregular")
      .def_property_readonly(
          "std_n", [](const E& e) { return unless_missing(e.std_n); },
          "irregular motion: standard deviation of the dynamic tension [N]; None when regular")
      .def_property_readonly(
          "zero_upcrossing_period_s",
          [](const E& e) { return unless_missing(e.zero_upcrossing_period_s); },
          "irregular motion: mean zero up-crossing period 2 pi sqrt(m0 / m2) [s]; None when "
          "regular")
      .def_property_readonly(
          "most_probable_max_n", [](const E& e) { return unless_missing(e.most_probable_max_n); },
          "irregular motion: most probable maximum tension in the request's duration, "
          "mean + sigma sqrt(2 ln N) [N]; None when regular")
      .def("__repr__", [](const E& e) {
        return e.std_n >= 0.0 ? fmt::format("DynamicTensionEnd(s_m={}, mean_n={}, std_n={})", e.s_m,
                                            e.mean_n, e.std_n)
                              : fmt::format("DynamicTensionEnd(s_m={}, mean_n={}, amplitude_n={})",
                                            e.s_m, e.mean_n, e.amplitude_n);
      });
}

void bind_tension(py::module_& module) {
  using T = DynamicTension;
  py::class_<T>(module, "DynamicTension",
                "The dynamic tension of one excitation (one period of a regular motion, or the "
                "irregular motion) with the Morison drag linearised about the response and "
                "iterated to its fixed point. Arrays are over the request's stations s_m.")
      .def_readonly("irregular", &T::irregular)
      .def_property_readonly(
          "period_s",
          [](const T& t) { return t.irregular ? std::nullopt : std::optional(t.period_s); },
          "regular motion: the period [s]; None when irregular")
      .def_property_readonly(
          "omega_rad_s",
          [](const T& t) { return t.irregular ? std::nullopt : std::optional(t.omega_rad_s); },
          "regular motion: 2 pi / period [rad/s]; None when irregular")
      .def_property_readonly(
          "s_m", [](const T& t) { return owned_array(t.s_m); },
          "stations: unstretched arc length from end a [m]")
      .def_property_readonly(
          "mean_n", [](const T& t) { return owned_array(t.mean_n); }, "static tension T0(s) [N]")
      .def_property_readonly(
          "amplitude_n", [](const T& t) { return array_or_none(t.amplitude_n); },
          "regular motion: |tau(s)| [N]; None when irregular")
      .def_property_readonly(
          "phase_deg", [](const T& t) { return array_or_none(t.phase_deg); },
          "regular motion: phase of tau(s) [deg]; None when irregular")
      .def_property_readonly(
          "std_n", [](const T& t) { return array_or_none(t.std_n); },
          "irregular motion: sigma_tau(s) [N]; None when regular")
      .def_property_readonly(
          "motion_m", [](const T& t) { return owned_array(t.motion_m); },
          "displacement amplitude |x(s)| (regular) or its standard deviation (irregular) [m]")
      .def_property_readonly(
          "normal_damping_n_s_per_m2",
          [](const T& t) { return owned_array(t.normal_damping_n_s_per_m2); },
          "the linearised normal drag c_n(s) [N s/m per m], on top of the sections' damping")
      .def_property_readonly(
          "tangential_damping_n_s_per_m2",
          [](const T& t) { return owned_array(t.tangential_damping_n_s_per_m2); },
          "the linearised tangential drag c_t(s) [N s/m per m]")
      .def_readonly("fairlead", &T::fairlead, "DynamicTensionEnd at end b (s = L)")
      .def_readonly("anchor", &T::anchor, "DynamicTensionEnd at end a (s = 0)")
      .def_property_readonly(
          "spectrum_omega_rad_s", [](const T& t) { return array_or_none(t.spectrum_omega_rad_s); },
          "irregular motion: the frequency grid [rad/s]; None when regular")
      .def_property_readonly(
          "fairlead_spectrum_n2_s_per_rad",
          [](const T& t) { return array_or_none(t.fairlead_spectrum_n2_s_per_rad); },
          "irregular motion: tension spectrum at the fairlead [N^2 s/rad]; None when regular")
      .def_property_readonly(
          "anchor_spectrum_n2_s_per_rad",
          [](const T& t) { return array_or_none(t.anchor_spectrum_n2_s_per_rad); },
          "irregular motion: tension spectrum at the anchor [N^2 s/rad]; None when regular")
      .def_readonly("iterations", &T::iterations,
                    "fixed-point iterations (linear solves of every frequency)")
      .def_property_readonly(
          "residual", [](const T& t) { return unless_missing(t.residual); },
          "relative residual of the velocity scales at the final iterate [-]; None when no "
          "response was computed")
      .def_readonly("converged", &T::converged,
                    "True only when the residual reached the request's tolerance")
      .def_property_readonly(
          "relative_error_estimate",
          [](const T& t) { return unless_missing(t.relative_error_estimate); },
          "estimated relative error of the tension [-]; None when none")
      .def_readonly("diagnostic", &T::diagnostic, "empty when converged, else why not")
      .def("__repr__", [](const T& t) {
        return fmt::format("DynamicTension({}, {} stations, {} iterations, {})",
                           t.irregular ? "irregular" : fmt::format("period {} s", t.period_s),
                           t.s_m.size(), t.iterations, t.converged ? "converged" : "not converged");
      });
}

}  // namespace

void bind_dynamic_tension(py::module_& module) {
  bind_end(module);
  bind_tension(module);
}

}  // namespace catena::python
