// SPDX-License-Identifier: MIT
// The shared statics (catena::StaticSolution, solve_statics) and the dimensionless groups.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::python {
namespace {

// Evaluates f(s) at every station of `s_m` (any shape) into a new array of that shape.
template <class Function>
py::array_t<double> at_stations(const py::array_t<double, py::array::forcecast>& s_m, Function f) {
  const py::buffer_info in = s_m.request();
  py::array_t<double> out(in.shape);
  const double* s = static_cast<const double*>(in.ptr);
  double* values = out.mutable_data();
  for (py::ssize_t i = 0; i < in.size; ++i) values[i] = f(s[i]);
  return out;
}

// Evaluates the vector function f(s) at every station into an array of shape (n, 2): columns x, z.
template <class Function>
py::array_t<double> vectors_at_stations(const py::array_t<double, py::array::forcecast>& s_m,
                                        Function f) {
  const py::buffer_info in = s_m.request();
  py::array_t<double> out({in.size, py::ssize_t(2)});
  const double* s = static_cast<const double*>(in.ptr);
  auto view = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < in.size; ++i) {
    const Vec2 v = f(s[i]);
    view(i, 0) = v.x();
    view(i, 1) = v.y();
  }
  return out;
}

// `problem` is a copy: the C++ work reads nothing a Python thread could change meanwhile.
StaticSolution solve_statics_released(Problem problem,
                                      double relative_tolerance,
                                      int max_iterations) {
  StaticsOptions options;
  options.relative_tolerance = relative_tolerance;
  options.max_iterations = max_iterations;
  const py::gil_scoped_release release;
  return solve_statics(problem, options);
}

void bind_static_solution(py::module_& module) {
  using S = StaticSolution;
  py::class_<S>(
      module, "Statics",
      "The static equilibrium (elastic catenary): end forces and closed forms at any unstretched "
      "arc length s [m] in [0, L]. Functions of s accept a number or an array.")
      .def_property_readonly("horizontal_force_n", &S::horizontal_force_n,
                             "H, constant along the cable or line [N]")
      .def_property_readonly("vertical_force_a_n", &S::vertical_force_a_n, "V_A at support a [N]")
      .def_property_readonly(
          "vertical_force_b_n", [](const S& s) { return s.vertical_force_n(s.cable().length_m); },
          "V(L) [N]")
      .def_property_readonly(
          "tension_a_n", [](const S& s) { return s.tension_n(0.0); }, "T at a [N]")
      .def_property_readonly(
          "tension_b_n", [](const S& s) { return s.tension_n(s.cable().length_m); }, "T at b [N]")
      .def_property_readonly(
          "stretched_length_m", [](const S& s) { return s.stretched_length_m(s.cable().length_m); },
          "stretched length of the whole cable [m]")
      .def_readonly("iterations", &S::iterations, "Newton iterations")
      .def_readonly("closure_error_m", &S::closure_error_m, "|r(L) - (b - a)| at the solution [m]")
      .def_readonly("converged", &S::converged,
                    "False when Newton did not close the chord (see message)")
      .def_readonly("message", &S::message, "why it stopped when not converged")
      .def_property_readonly("cable", &S::cable,
                             "the uniform cable (for a general line only length_m, the total)")
      .def_property_readonly("is_line", &S::is_line, "True when solved for a general line")
      .def_property_readonly("line", &S::line, "the line (one segment for a uniform cable)")
      .def_property_readonly("has_contact", &S::has_contact,
                             "True when a grounded length rests on the seabed")
      .def_property_readonly(
          "grounded_length_m", &S::grounded_length_m,
          "total unstretched length resting on the seabed [m] (all contact intervals); 0 without "
          "contact")
      .def_property_readonly(
          "contact_intervals",
          [](const S& s) {
            std::vector<std::pair<double, double>> intervals;
            for (const ContactInterval& c : s.contact_intervals())
              intervals.emplace_back(c.s_begin_m, c.s_end_m);
            return intervals;
          },
          "stretches resting on the seabed, [(s_begin_m, s_end_m)] in order of s (unstretched arc "
          "lengths [m]); empty without contact")
      .def_property_readonly("slack_length_m", &S::slack_length_m,
                             "unstretched length of a slack line (H = 0) lying in a heap on the "
                             "seabed beyond the span [m]; 0 otherwise")
      .def_property_readonly("anchor_grounded", &S::anchor_grounded,
                             "True when end A rests on the seabed")
      .def_property_readonly("anchor_horizontal_force_n", &S::anchor_horizontal_force_n,
                             "horizontal force on end A: with A on the seabed, H less the seabed "
                             "friction; H otherwise [N]")
      .def_property_readonly("lowest_point_s_m", &S::lowest_point_s_m,
                             "arc length of the lowest point [m]")
      .def(
          "vertical_force_n",
          [](const S& st, py::array_t<double, py::array::forcecast> s) {
            return at_stations(s, [&](double x) { return st.vertical_force_n(x); });
          },
          py::arg("s_m"), "V(s) [N]; at a point attachment, the value on the side of b")
      .def(
          "tension_n",
          [](const S& st, py::array_t<double, py::array::forcecast> s) {
            return at_stations(s, [&](double x) { return st.tension_n(x); });
          },
          py::arg("s_m"), "T(s) [N]")
      .def(
          "strain",
          [](const S& st, py::array_t<double, py::array::forcecast> s) {
            return at_stations(s, [&](double x) { return st.strain(x); });
          },
          py::arg("s_m"), "static strain T/EA [-]")
      .def(
          "angle_rad",
          [](const S& st, py::array_t<double, py::array::forcecast> s) {
            return at_stations(s, [&](double x) { return st.angle_rad(x); });
          },
          py::arg("s_m"), "tangent angle above the horizontal [rad]")
      .def(
          "position_m",
          [](const S& st, py::array_t<double, py::array::forcecast> s) {
            return vectors_at_stations(s, [&](double x) { return st.position_m(x); });
          },
          py::arg("s_m"), "positions r(s), shape (n, 2): x, z [m]")
      .def(
          "tangent",
          [](const S& st, py::array_t<double, py::array::forcecast> s) {
            return vectors_at_stations(s, [&](double x) { return st.tangent(x); });
          },
          py::arg("s_m"), "unit tangents, shape (n, 2)")
      .def(
          "normal",
          [](const S& st, py::array_t<double, py::array::forcecast> s) {
            return vectors_at_stations(s, [&](double x) { return st.normal(x); });
          },
          py::arg("s_m"), "unit in-plane normals, shape (n, 2)")
      .def("brief_report", &S::brief_report)
      .def("__repr__", [](const S& s) { return "Statics(" + s.brief_report() + ")"; });
}

void bind_groups(py::module_& module) {
  using G = DimensionlessGroups;
  py::class_<G>(module, "Groups", "The dimensionless groups of docs/explanation/physics.md.")
      .def_readonly("chord_angle_rad", &G::chord_angle_rad)
      .def_readonly("s_at_chord_angle_m", &G::s_at_chord_angle_m)
      .def_readonly("t0_n", &G::t0_n, "tension where the tangent is parallel to the chord [N]")
      .def_readonly("eps", &G::eps)
      .def_readonly("lambda2", &G::lambda2, "Irvine's lambda^2 (inf when inextensible)")
      .def_readonly("mass_ratio", &G::mass_ratio, "h = m / M")
      .def_readonly("has_apex_parameterization", &G::has_apex_parameterization)
      .def_readonly("catenary_parameter_m", &G::catenary_parameter_m, "Gale's a = H/W0 [m]")
      .def_readonly("sigma1", &G::sigma1)
      .def_readonly("sigma2", &G::sigma2)
      .def_readonly("xi1", &G::xi1)
      .def_readonly("xi2", &G::xi2)
      .def_readonly("height_over_span", &G::height_over_span)
      .def_readonly("sag_parameter", &G::sag_parameter)
      .def_readonly("taut_frequency_scale_rad_s", &G::taut_frequency_scale_rad_s)
      .def_readonly("gale_frequency_scale_rad_s", &G::gale_frequency_scale_rad_s)
      .def("k_l_over_pi", &G::k_l_over_pi, py::arg("omega_rad_s"))
      .def("gale_ratio", &G::gale_ratio, py::arg("omega_rad_s"));
}

}  // namespace

void bind_statics(py::module_& module) {
  bind_static_solution(module);
  bind_groups(module);
  module.def(
      "solve_statics", &solve_statics_released, py::arg("problem"), py::kw_only(),
      py::arg("relative_tolerance") = StaticsOptions{}.relative_tolerance,
      py::arg("max_iterations") = StaticsOptions{}.max_iterations,
      "Solves the statics of `problem` (Newton on (H, V_A)). Bad input raises catena.InvalidInput; "
      "a "
      "Newton iteration that does not close the chord returns Statics with converged False.");
  module.def(
      "dimensionless_groups",
      [](const Problem& problem, const StaticSolution& statics) {
        return compute_dimensionless_groups(problem, statics);
      },
      py::arg("problem"), py::arg("statics"),
      "The groups (eps, lambda2, Gale's xi, ...) of a solved problem.");
}

}  // namespace catena::python
