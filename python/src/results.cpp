// SPDX-License-Identifier: MIT
// What the solvers return (docs/reference/json-layout.md): summaries, modes with their shapes as
// stations x modes arrays, forced responses and checks. Every array is a new read-only numpy array
// owning a copy of its values, so none outlives or aliases the C++ object it came from.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/verification/check_result.hpp"

namespace catena::python {
namespace {

// One column per mode of the field `field` (a Vector of each Mode), rows the stations; None when a
// mode lacks the field or the modes disagree on the stations.
py::object mode_table(const std::vector<Mode>& modes, Vector Mode::*field) {
  if (modes.empty() || (modes.front().*field).size() == 0) return py::none();
  const Index stations = (modes.front().*field).size();
  for (const Mode& mode : modes) {
    if ((mode.*field).size() != stations) return py::none();
  }
  py::array_t<double> table({py::ssize_t(stations), py::ssize_t(modes.size())});
  auto view = table.mutable_unchecked<2>();
  for (std::size_t k = 0; k < modes.size(); ++k) {
    for (Index j = 0; j < stations; ++j) view(j, py::ssize_t(k)) = (modes[k].*field)(j);
  }
  return read_only(table);
}

// The value of `field` for every mode, lowest first.
template <class T>
py::array_t<T> mode_column(const std::vector<Mode>& modes, T Mode::*field) {
  py::array_t<T> column(static_cast<py::ssize_t>(modes.size()));
  for (std::size_t k = 0; k < modes.size(); ++k) column.mutable_data()[k] = modes[k].*field;
  read_only(column);
  return column;
}

// A per-mode quantity that is -1 when not asked (tension, modal mass): None then.
py::object optional_column(const std::vector<Mode>& modes, double Mode::*field) {
  for (const Mode& mode : modes) {
    if (mode.*field < 0.0) return py::none();
  }
  return mode_column(modes, field);
}

/// The shapes of one plane as tables: rows are the stations s_m, columns the modes, lowest first.
struct ModeShapes {
  py::object s_m, u, w, v, tension_n;
  std::vector<std::string> normalised_by;
};

py::object shapes_of(const ModalResult& result) {
  if (result.modes.empty() || result.modes.front().s_m.size() == 0) return py::none();
  ModeShapes shapes;
  shapes.s_m = owned_array(result.modes.front().s_m);
  shapes.u = mode_table(result.modes, &Mode::u);
  shapes.w = mode_table(result.modes, &Mode::w);
  shapes.v = mode_table(result.modes, &Mode::v);
  shapes.tension_n = mode_table(result.modes, &Mode::tension_n);
  for (const Mode& mode : result.modes) shapes.normalised_by.push_back(mode.normalised_by);
  return py::cast(std::move(shapes));
}

void bind_summary(py::module_& module) {
  using S = SolverSummary;
  py::class_<S>(module, "Summary",
                "How a result was obtained (docs/contributing/architecture.md, \"Errors\").")
      .def_property_readonly(
          "status", [](const S& s) { return to_string(s.termination); },
          "'converged', 'no-convergence', 'numerical-failure' or 'not-applicable'")
      .def_property_readonly("usable", &S::is_usable,
                             "converged, or no-convergence with partial results")
      .def_readonly("message", &S::message, "why it stopped, with numbers")
      .def_readonly("solver", &S::solver)
      .def_readonly("resolution", &S::resolution, "the resolution used, in words")
      .def_readonly("iterations", &S::iterations, "solver-specific count (-1: not counted)")
      .def_readonly("operations", &S::operations,
                    "mat-vecs, RHS evaluations, ... (-1: not counted)")
      .def_readonly("max_relative_error_estimate", &S::max_error_estimate,
                    "largest relative error estimate over the returned frequencies (-1: none)")
      .def_readonly("max_residual", &S::max_residual, "(-1: not applicable)")
      .def_readonly("wall_time_s", &S::wall_time_s)
      .def_readonly("warnings", &S::warnings)
      .def_readonly("notes", &S::notes)
      .def("brief_report", &S::brief_report)
      .def("full_report", &S::full_report)
      .def("__repr__", [](const S& s) { return "Summary(" + s.brief_report() + ")"; });
}

void bind_mode(py::module_& module) {
  py::class_<Mode>(module, "Mode",
                   "One natural mode; shapes normalised as docs/reference/json-layout.md says.")
      .def_readonly("index", &Mode::index, "1-based, lowest first, within its plane")
      .def_readonly("omega_rad_s", &Mode::omega_rad_s)
      .def_readonly("frequency_hz", &Mode::frequency_hz)
      .def_readonly("k_l_over_pi", &Mode::k_l_over_pi)
      .def_readonly("gale_ratio", &Mode::gale_ratio, "omega / sqrt(g/a), None when H = 0")
      .def_readonly("relative_error_estimate", &Mode::relative_error_estimate, "(-1: none)")
      .def_readonly("multiplicity", &Mode::multiplicity)
      .def_property_readonly(
          "s_m", [](const Mode& m) { return owned_array(m.s_m); }, "stations [m]")
      .def_property_readonly(
          "u", [](const Mode& m) { return owned_array(m.u); }, "tangential shape")
      .def_property_readonly(
          "w", [](const Mode& m) { return owned_array(m.w); }, "in-plane normal shape")
      .def_property_readonly(
          "v", [](const Mode& m) { return owned_array(m.v); }, "out-of-plane shape")
      .def_property_readonly(
          "tension_n", [](const Mode& m) { return owned_array(m.tension_n); },
          "dynamic tension along the cable [N per unit normalised amplitude]")
      .def_readonly("normalised_by", &Mode::normalised_by)
      .def_readonly("max_abs_tension_n", &Mode::max_abs_tension_n, "(-1: not asked)")
      .def_readonly("modal_mass_kg", &Mode::modal_mass_kg, "(-1: not asked)")
      .def("__repr__", [](const Mode& m) {
        return fmt::format("Mode(index={}, omega_rad_s={:.12g}, relative_error_estimate={:.3g})",
                           m.index, m.omega_rad_s, m.relative_error_estimate);
      });
}

void bind_shapes(py::module_& module) {
  py::class_<ModeShapes>(
      module, "ModeShapes",
      "Mode shapes of one plane: arrays of shape (stations, modes), lowest mode first; "
      "u, w in plane, v out of plane (None for the other plane).")
      .def_readonly("s_m", &ModeShapes::s_m, "stations, unstretched arc length [m]")
      .def_readonly("u", &ModeShapes::u, "tangential displacement (in plane)")
      .def_readonly("w", &ModeShapes::w, "normal displacement (in plane)")
      .def_readonly("v", &ModeShapes::v, "out-of-plane displacement")
      .def_readonly("tension_n", &ModeShapes::tension_n, "dynamic tension [N], None unless asked")
      .def_readonly("normalised_by", &ModeShapes::normalised_by,
                    "component that fixed each mode's scale");
}

void bind_modal_result(py::module_& module) {
  using R = ModalResult;
  py::class_<R>(module, "Modes", "The modes of one plane, lowest first, with their summary.")
      .def_property_readonly("plane", [](const R& r) { return std::string(to_string(r.plane)); })
      .def_readonly("modes", &R::modes)
      .def_readonly("summary", &R::summary)
      .def_readonly("proved_count_below_top", &R::proved_count_below_top,
                    "(-1: the method has no count)")
      .def_property_readonly("omega_rad_s",
                             [](const R& r) { return mode_column(r.modes, &Mode::omega_rad_s); })
      .def_property_readonly("frequency_hz",
                             [](const R& r) { return mode_column(r.modes, &Mode::frequency_hz); })
      .def_property_readonly("k_l_over_pi",
                             [](const R& r) { return mode_column(r.modes, &Mode::k_l_over_pi); })
      .def_property_readonly(
          "relative_error_estimate",
          [](const R& r) { return mode_column(r.modes, &Mode::relative_error_estimate); },
          "each mode's own estimate (-1: none)")
      .def_property_readonly("multiplicity",
                             [](const R& r) { return mode_column(r.modes, &Mode::multiplicity); })
      .def_property_readonly(
          "max_abs_tension_n",
          [](const R& r) { return optional_column(r.modes, &Mode::max_abs_tension_n); },
          "[N], None unless tension was asked")
      .def_property_readonly(
          "modal_mass_kg",
          [](const R& r) { return optional_column(r.modes, &Mode::modal_mass_kg); },
          "[kg], None unless shapes were asked")
      .def_property_readonly("shapes", &shapes_of, "ModeShapes, None unless shapes were asked")
      .def("__len__", [](const R& r) { return r.modes.size(); })
      .def("__repr__", [](const R& r) {
        return fmt::format("Modes({}, {} modes, {})", to_string(r.plane), r.modes.size(),
                           to_string(r.summary.termination));
      });
}

void bind_forced(py::module_& module) {
  using F = ForcedResponse;
  py::class_<F>(module, "ForcedResponse", "Response to one forcing frequency (amplitudes).")
      .def_readonly("omega_rad_s", &F::omega_rad_s)
      .def_property_readonly("s_m", [](const F& f) { return owned_array(f.s_m); })
      .def_property_readonly("u_m", [](const F& f) { return owned_array(f.u); })
      .def_property_readonly("w_m", [](const F& f) { return owned_array(f.w); })
      .def_property_readonly("v_m", [](const F& f) { return owned_array(f.v); })
      .def_property_readonly("tension_n", [](const F& f) { return owned_array(f.tension_n); })
      .def_readonly("max_abs_tension_n", &F::max_abs_tension_n)
      .def_readonly("relative_error_estimate", &F::relative_error_estimate, "(-1: none)")
      .def_readonly("diagnostic", &F::diagnostic,
                    "empty when fine, else why there is no finite answer")
      .def_readonly("at_resonance", &F::at_resonance)
      .def_readonly("near_resonance", &F::near_resonance);
}

void bind_solver_output(py::module_& module) {
  using O = SolverOutput;
  py::class_<O>(module, "SolverResult",
                "Everything one solver produced for one problem and request.")
      .def_readonly("solver", &O::solver)
      .def_readonly("inplane", &O::inplane, "Modes, or None when not asked")
      .def_readonly("outofplane", &O::outofplane, "Modes, or None when not asked")
      .def_readonly("forced", &O::forced, "list of ForcedResponse")
      .def_readonly("summary", &O::summary, "the overall Summary")
      .def("__repr__", [](const O& o) { return "SolverResult(" + o.summary.brief_report() + ")"; });
}

void bind_check(py::module_& module) {
  using C = CheckResult;
  py::class_<C>(module, "Check", "One cross-check and its verdict (docs/reference/verdicts.md).")
      .def_readonly("check", &C::check)
      .def_readonly("compare", &C::compare)
      .def_readonly("plane", &C::plane)
      .def_readonly("mode", &C::mode)
      .def_readonly("value_a", &C::value_a)
      .def_readonly("value_b", &C::value_b)
      .def_readonly("measured", &C::measured)
      .def_readonly("tolerance", &C::tolerance)
      .def_property_readonly(
          "verdict", [](const C& c) { return to_string(c.verdict); },
          "'PASS', 'FAIL', 'SOURCE', 'WARN' or 'SKIP'")
      .def_readonly("detail", &C::detail)
      .def("__repr__", [](const C& c) {
        return fmt::format("Check({} {} {} mode {}: {})", c.check, c.compare, c.plane, c.mode,
                           to_string(c.verdict));
      });
}

}  // namespace

void bind_results(py::module_& module) {
  bind_summary(module);
  bind_mode(module);
  bind_shapes(module);
  bind_modal_result(module);
  bind_forced(module);
  bind_solver_output(module);
  bind_check(module);
}

}  // namespace catena::python
