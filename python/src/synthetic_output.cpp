// SPDX-License-Identifier: MIT
// A SolverResult built from given damped roots and complex shapes, for the Python tests only
// (python/tests/test_damping.py): it checks the conversion of damped results (complex eigenvalues,
// complex shape tables, overdamped roots, the forced response's quadrature parts) to numpy on
// values the test chose, independently of any solver.
#include <pybind11/complex.h>
#include <pybind11/stl.h>

#include <cmath>
#include <complex>

#include "bindings.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/modal_result.hpp"

namespace catena::python {
namespace {

using Complex = std::complex<double>;
using ComplexValues = std::vector<Complex>;

// Splits complex values into the result structs' real and imaginary parts.
void split(const ComplexValues& values, Vector& real, Vector& imag) {
  real.resize(Index(values.size()));
  imag.resize(Index(values.size()));
  for (std::size_t j = 0; j < values.size(); ++j) {
    real[Index(j)] = values[j].real();
    imag[Index(j)] = values[j].imag();
  }
}

// A root lambda = -delta + i omega_d with the definitions of modal_result.hpp.
Mode root_mode(int index, Complex lambda) {
  Mode mode;
  mode.index = index;
  mode.omega_rad_s = lambda.imag();
  mode.frequency_hz = lambda.imag() / (2.0 * M_PI);
  mode.decay_rate_1_s = -lambda.real();
  mode.damping_ratio = std::abs(lambda) > 0.0 ? -lambda.real() / std::abs(lambda) : 0.0;
  return mode;
}

// eigenvalues[k] with in-plane shapes u[k], w[k], tension[k] on the stations s_m; overdamped
// roots -delta for each delta of overdamped_decay_rates_1_s; one forced response at
// forced_omega_rad_s with the complex normal amplitude forced_w_m.
SolverOutput synthetic_damped_output(const ComplexValues& eigenvalues,
                                     const std::vector<double>& s_m,
                                     const std::vector<ComplexValues>& u,
                                     const std::vector<ComplexValues>& w,
                                     const std::vector<ComplexValues>& tension_n,
                                     const std::vector<double>& overdamped_decay_rates_1_s,
                                     double forced_omega_rad_s,
                                     const ComplexValues& forced_w_m) {
  if (u.size() != eigenvalues.size() || w.size() != eigenvalues.size() ||
      tension_n.size() != eigenvalues.size()) {
    throw InvalidInput("_synthetic_damped_output: one u, w and tension_n per eigenvalue");
  }
  ModalResult plane;
  plane.plane = Plane::InPlane;
  plane.summary.termination = Termination::Converged;
  const Vector stations = Eigen::Map<const Vector>(s_m.data(), Index(s_m.size()));
  for (std::size_t k = 0; k < eigenvalues.size(); ++k) {
    Mode mode = root_mode(int(k) + 1, eigenvalues[k]);
    mode.s_m = stations;
    split(u[k], mode.u, mode.u_imag);
    split(w[k], mode.w, mode.w_imag);
    split(tension_n[k], mode.tension_n, mode.tension_imag_n);
    mode.normalised_by = "w";
    plane.modes.push_back(mode);
  }
  for (std::size_t k = 0; k < overdamped_decay_rates_1_s.size(); ++k) {
    plane.overdamped.push_back(root_mode(int(k) + 1, Complex(-overdamped_decay_rates_1_s[k], 0.0)));
  }
  SolverOutput output;
  output.solver = "synthetic";
  output.summary.termination = Termination::Converged;
  output.inplane = plane;
  ForcedResponse response;
  response.omega_rad_s = forced_omega_rad_s;
  response.s_m = stations;
  split(forced_w_m, response.w, response.w_imag);
  output.forced.push_back(response);
  return output;
}

}  // namespace

void bind_synthetic_output(py::module_& module) {
  module.def("_synthetic_damped_output", &synthetic_damped_output, py::arg("eigenvalues"),
             py::arg("s_m"), py::arg("u"), py::arg("w"), py::arg("tension_n"),
             py::arg("overdamped_decay_rates_1_s"), py::arg("forced_omega_rad_s"),
             py::arg("forced_w_m"),
             "Tests only: a SolverResult holding the given damped roots and complex shapes.");
}

}  // namespace catena::python
