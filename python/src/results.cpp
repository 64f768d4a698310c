// SPDX-License-Identifier: MIT
// What the solvers return (docs/reference/json-layout.md): summaries, modes with their shapes as
// stations x modes arrays, forced responses and checks. Every array is a new read-only numpy array
// owning a copy of its values, so none outlives or aliases the C++ object it came from.
#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <complex>

#include "bindings.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/verification/check_result.hpp"

namespace catena::python {
namespace {

using Complex = std::complex<double>;

// A damped (complex) field is held as its real part `real` and its imaginary part `imag`, the
// latter empty when undamped (modal_result.hpp). Python gets a complex array real + 1j imag when
// the imaginary part is present, else the real array, so an undamped result is unchanged.
py::array complex_or_real(const Vector& real, const Vector& imag) {
  if (imag.size() == 0) return owned_array(real);
  py::array_t<Complex> values(static_cast<py::ssize_t>(real.size()));
  for (Index j = 0; j < real.size(); ++j) values.mutable_data()[j] = Complex(real[j], imag[j]);
  return read_only(values);
}

// The root lambda = -delta + i omega_d of a mode (i omega when undamped; never a -0 real part).
Complex eigenvalue_of(const Mode& mode) {
  return {mode.decay_rate_1_s == 0.0 ? 0.0 : -mode.decay_rate_1_s, mode.omega_rad_s};
}

// One column per mode of the field `field` (a Vector of each Mode), rows the stations; None when a
// mode lacks the field or the modes disagree on the stations. Complex (real + 1j imag) when some
// mode has the imaginary part `imag` (a mode without it has a real column).
py::object mode_table(const std::vector<Mode>& modes, Vector Mode::*field, Vector Mode::*imag) {
  if (modes.empty() || (modes.front().*field).size() == 0) return py::none();
  const Index stations = (modes.front().*field).size();
  bool complex = false;
  for (const Mode& mode : modes) {
    if ((mode.*field).size() != stations) return py::none();
    if ((mode.*imag).size() != 0 && (mode.*imag).size() != stations) return py::none();
    complex = complex || (mode.*imag).size() != 0;
  }
  const auto fill = [&](auto& table, auto value_at) {
    auto view = table.template mutable_unchecked<2>();
    for (std::size_t k = 0; k < modes.size(); ++k) {
      for (Index j = 0; j < stations; ++j) view(j, py::ssize_t(k)) = value_at(modes[k], j);
    }
  };
  const std::vector<py::ssize_t> shape{py::ssize_t(stations), py::ssize_t(modes.size())};
  if (!complex) {
    py::array_t<double> table(shape);
    fill(table, [&](const Mode& mode, Index j) { return (mode.*field)(j); });
    return read_only(table);
  }
  py::array_t<Complex> table(shape);
  fill(table, [&](const Mode& mode, Index j) {
    return Complex((mode.*field)(j), (mode.*imag).size() ? (mode.*imag)(j) : 0.0);
  });
  return read_only(table);
}

// Each mode's root lambda = -delta + i omega_d, lowest first.
py::array eigenvalue_column(const std::vector<Mode>& modes) {
  py::array_t<Complex> column(static_cast<py::ssize_t>(modes.size()));
  for (std::size_t k = 0; k < modes.size(); ++k) column.mutable_data()[k] = eigenvalue_of(modes[k]);
  return read_only(column);
}

// The overdamped roots of a plane as a plane of their own (the same fields, arrays and summary as
// its oscillating modes; no mode count, which covers the oscillating modes only).
ModalResult overdamped_of(const ModalResult& result) {
  ModalResult roots;
  roots.plane = result.plane;
  roots.modes = result.overdamped;
  roots.summary = result.summary;
  return roots;
}

// The value of `field` for every mode, lowest first.
template <class T>
py::array_t<T> mode_column(const std::vector<Mode>& modes, T Mode::*field) {
  py::array_t<T> column(static_cast<py::ssize_t>(modes.size()));
  for (std::size_t k = 0; k < modes.size(); ++k) column.mutable_data()[k] = modes[k].*field;
  read_only(column);
  return column;
}

// A per-mode quantity that is -1 when missing (an error estimate, a tension or modal mass not
// asked): NaN for each mode that lacks it.
py::array_t<double> column_nan_if_missing(const std::vector<Mode>& modes, double Mode::*field) {
  py::array_t<double> column(static_cast<py::ssize_t>(modes.size()));
  for (std::size_t k = 0; k < modes.size(); ++k) {
    column.mutable_data()[k] = nan_if_missing(modes[k].*field);
  }
  read_only(column);
  return column;
}

// A per-mode quantity only some requests ask for (tension, modal mass): None when no mode has it,
// else NaN for a mode that lacks it.
py::object optional_column(const std::vector<Mode>& modes, double Mode::*field) {
  const bool any =
      std::any_of(modes.begin(), modes.end(), [&](const Mode& mode) { return mode.*field >= 0.0; });
  if (!any) return py::none();
  return column_nan_if_missing(modes, field);
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
  shapes.u = mode_table(result.modes, &Mode::u, &Mode::u_imag);
  shapes.w = mode_table(result.modes, &Mode::w, &Mode::w_imag);
  shapes.v = mode_table(result.modes, &Mode::v, &Mode::v_imag);
  shapes.tension_n = mode_table(result.modes, &Mode::tension_n, &Mode::tension_imag_n);
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
      .def_property_readonly(
          "iterations", [](const S& s) { return unless_missing(s.iterations); },
          "solver-specific count (restarts, Newton steps, series terms), None when not counted")
      .def_property_readonly(
          "operations", [](const S& s) { return unless_missing(s.operations); },
          "mat-vecs, RHS evaluations, ..., None when not counted")
      .def_property_readonly(
          "max_relative_error_estimate",
          [](const S& s) { return unless_missing(s.max_error_estimate); },
          "largest relative error estimate over the returned frequencies [-], None when none")
      .def_property_readonly(
          "max_residual", [](const S& s) { return unless_missing(s.max_residual); },
          "largest relative eigen-residual [-], None when not applicable")
      .def_property_readonly(
          "accuracy_target", [](const S& s) { return unless_missing(s.accuracy_target); },
          "relative accuracy asked of each frequency [-], None when none was asked")
      .def_readonly("missed_modes", &S::missed_modes,
                    "the modes whose estimate exceeds accuracy_target, one line each")
      .def_property_readonly(
          "wall_time_s", [](const S& s) { return unless_missing(s.wall_time_s); },
          "wall-clock time of the solve [s], None when it did not run")
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
      .def_readonly("omega_rad_s", &Mode::omega_rad_s,
                    "natural frequency [rad/s]; damped: omega_d = Im lambda")
      .def_property_readonly("eigenvalue", &eigenvalue_of,
                             "the root lambda = -delta + i omega_d [1/s] (i omega when undamped)")
      .def_readonly("decay_rate_1_s", &Mode::decay_rate_1_s,
                    "delta = -Re lambda [1/s]: amplitude ~ exp(-delta t); 0 when undamped")
      .def_readonly("damping_ratio", &Mode::damping_ratio,
                    "zeta = delta / |lambda| [-]; 0 when undamped, 1 for an overdamped root")
      .def_property_readonly(
          "decay_rate_error_estimate",
          [](const Mode& m) { return unless_missing(m.decay_rate_error_estimate); },
          "the solver's estimate of the relative error of delta on its own [-], None when none "
          "(always None when undamped)")
      .def_readonly("frequency_hz", &Mode::frequency_hz)
      .def_readonly("k_l_over_pi", &Mode::k_l_over_pi)
      .def_readonly("gale_ratio", &Mode::gale_ratio, "omega / sqrt(g/a), None when H = 0")
      .def_property_readonly(
          "relative_error_estimate",
          [](const Mode& m) { return unless_missing(m.relative_error_estimate); },
          "the solver's own estimate of the relative error of omega [-], None when none")
      .def_readonly("multiplicity", &Mode::multiplicity)
      .def_readonly("meets_target", &Mode::meets_target,
                    "False when the estimate exceeds the summary's accuracy_target (or is missing "
                    "while one was asked)")
      .def_property_readonly(
          "s_m", [](const Mode& m) { return owned_array(m.s_m); }, "stations [m]")
      .def_property_readonly(
          "u", [](const Mode& m) { return complex_or_real(m.u, m.u_imag); },
          "tangential shape (complex when damped)")
      .def_property_readonly(
          "w", [](const Mode& m) { return complex_or_real(m.w, m.w_imag); },
          "in-plane normal shape (complex when damped)")
      .def_property_readonly(
          "v", [](const Mode& m) { return complex_or_real(m.v, m.v_imag); },
          "out-of-plane shape (complex when damped)")
      .def_property_readonly(
          "tension_n", [](const Mode& m) { return complex_or_real(m.tension_n, m.tension_imag_n); },
          "dynamic tension along the cable [N per unit normalised amplitude] (complex when "
          "damped)")
      .def_readonly("normalised_by", &Mode::normalised_by)
      .def_property_readonly(
          "max_abs_tension_n", [](const Mode& m) { return unless_missing(m.max_abs_tension_n); },
          "max |dynamic tension| [N], None unless tension was asked")
      .def_property_readonly(
          "modal_mass_kg", [](const Mode& m) { return unless_missing(m.modal_mass_kg); },
          "[kg], None unless shapes were asked")
      .def("__repr__", [](const Mode& m) {
        return fmt::format(
            "Mode(index={}, omega_rad_s={:.12g}{}, relative_error_estimate={})", m.index,
            m.omega_rad_s,
            m.decay_rate_1_s == 0.0 ? std::string()
                                    : fmt::format(", decay_rate_1_s={:.12g}, damping_ratio={:.6g}",
                                                  m.decay_rate_1_s, m.damping_ratio),
            m.relative_error_estimate < 0.0 ? std::string("None")
                                            : fmt::format("{:.3g}", m.relative_error_estimate));
      });
}

void bind_shapes(py::module_& module) {
  py::class_<ModeShapes>(
      module, "ModeShapes",
      "Mode shapes of one plane: arrays of shape (stations, modes), lowest mode first; "
      "u, w in plane, v out of plane (None for the other plane).")
      .def_readonly("s_m", &ModeShapes::s_m, "stations, unstretched arc length [m]")
      .def_readonly("u", &ModeShapes::u, "tangential displacement (in plane; complex when damped)")
      .def_readonly("w", &ModeShapes::w, "normal displacement (in plane; complex when damped)")
      .def_readonly("v", &ModeShapes::v, "out-of-plane displacement (complex when damped)")
      .def_readonly("tension_n", &ModeShapes::tension_n,
                    "dynamic tension [N], None unless asked (complex when damped)")
      .def_readonly("normalised_by", &ModeShapes::normalised_by,
                    "component that fixed each mode's scale");
}

void bind_modal_result(py::module_& module) {
  using R = ModalResult;
  py::class_<R>(module, "Modes", "The modes of one plane, lowest first, with their summary.")
      .def_property_readonly("plane", [](const R& r) { return std::string(to_string(r.plane)); })
      .def_readonly("modes", &R::modes)
      .def_readonly("summary", &R::summary)
      .def_property_readonly(
          "proved_count_below_top",
          [](const R& r) { return unless_missing(r.proved_count_below_top); },
          "eigenvalues proved to lie at or below the highest returned one, None when the method "
          "has no count")
      .def_property_readonly(
          "omega_rad_s", [](const R& r) { return mode_column(r.modes, &Mode::omega_rad_s); },
          "natural frequencies [rad/s]; damped: omega_d = Im lambda")
      .def_property_readonly(
          "eigenvalue", [](const R& r) { return eigenvalue_column(r.modes); },
          "complex roots lambda = -delta + i omega_d [1/s] (i omega when undamped)")
      .def_property_readonly(
          "decay_rate_1_s", [](const R& r) { return mode_column(r.modes, &Mode::decay_rate_1_s); },
          "delta = -Re lambda [1/s]; 0 when undamped")
      .def_property_readonly(
          "damping_ratio", [](const R& r) { return mode_column(r.modes, &Mode::damping_ratio); },
          "zeta = delta / |lambda| [-]; 0 when undamped")
      .def_property_readonly(
          "decay_rate_error_estimate",
          [](const R& r) {
            return column_nan_if_missing(r.modes, &Mode::decay_rate_error_estimate);
          },
          "each mode's relative error estimate of delta [-], NaN for a mode without one")
      .def_property_readonly(
          "overdamped", &overdamped_of,
          "the overdamped roots (real lambda = -delta, omega 0, zeta 1), ascending in delta, as "
          "Modes with the same fields (empty when none)")
      .def_property_readonly("frequency_hz",
                             [](const R& r) { return mode_column(r.modes, &Mode::frequency_hz); })
      .def_property_readonly("k_l_over_pi",
                             [](const R& r) { return mode_column(r.modes, &Mode::k_l_over_pi); })
      .def_property_readonly(
          "relative_error_estimate",
          [](const R& r) { return column_nan_if_missing(r.modes, &Mode::relative_error_estimate); },
          "each mode's own estimate [-], NaN for a mode without one")
      .def_property_readonly("multiplicity",
                             [](const R& r) { return mode_column(r.modes, &Mode::multiplicity); })
      .def_property_readonly(
          "max_abs_tension_n",
          [](const R& r) { return optional_column(r.modes, &Mode::max_abs_tension_n); },
          "[N], None unless tension was asked (NaN for a mode without it)")
      .def_property_readonly(
          "modal_mass_kg",
          [](const R& r) { return optional_column(r.modes, &Mode::modal_mass_kg); },
          "[kg], None unless shapes were asked (NaN for a mode without it)")
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
      .def_property_readonly(
          "u_m", [](const F& f) { return complex_or_real(f.u, f.u_imag); },
          "tangential amplitude [m]; damped: complex, the response is Re[u_m exp(i omega t)]")
      .def_property_readonly(
          "w_m", [](const F& f) { return complex_or_real(f.w, f.w_imag); },
          "normal amplitude [m] (complex when damped)")
      .def_property_readonly(
          "v_m", [](const F& f) { return complex_or_real(f.v, f.v_imag); },
          "out-of-plane amplitude [m] (complex when damped)")
      .def_property_readonly(
          "tension_n", [](const F& f) { return complex_or_real(f.tension_n, f.tension_imag_n); },
          "dynamic tension amplitude [N] (complex when damped)")
      .def_readonly("max_abs_tension_n", &F::max_abs_tension_n,
                    "max |tension| along the line [N] (the complex modulus when damped)")
      .def_property_readonly(
          "relative_error_estimate",
          [](const F& f) { return unless_missing(f.relative_error_estimate); },
          "estimated relative error of max_abs_tension_n [-], None when none")
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
      .def_readonly("dynamic_tension", &O::dynamic_tension,
                    "list of DynamicTension: one per period of a regular motion request, one for "
                    "an irregular one; empty when no motion was asked or the solver declined it "
                    "(the summary says why)")
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
