// SPDX-License-Identifier: MIT
// SolverResults built from given values, for the Python tests only: damped roots and complex
// shapes (python/tests/test_damping.py: complex eigenvalues, complex shape tables, overdamped
// roots, the forced response's quadrature parts) and a dynamic tension
// (python/tests/test_dynamic_tension.py: its profiles, ends, spectra and fixed-point report),
// converted to numpy on values the test chose, independently of any solver.
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

Vector vector_of(const std::vector<double>& values) {
  return Eigen::Map<const Vector>(values.data(), Index(values.size()));
}

// The end `j` of the profiles: regular ends carry amplitude and phase, irregular ones sigma, the
// up-crossing period and the most probable maximum (given: no solver's formula is re-derived here).
DynamicTensionEnd synthetic_end(const DynamicTension& t,
                                Index j,
                                double zero_upcrossing_period_s,
                                double most_probable_max_n) {
  DynamicTensionEnd end;
  end.s_m = t.s_m[j];
  end.mean_n = t.mean_n[j];
  if (t.irregular) {
    end.std_n = t.std_n[j];
    end.zero_upcrossing_period_s = zero_upcrossing_period_s;
    end.most_probable_max_n = most_probable_max_n;
  } else {
    end.amplitude_n = t.amplitude_n[j];
    end.phase_deg = t.phase_deg[j];
  }
  return end;
}

// One DynamicTension of the given profiles (tension_n: the amplitude when regular, sigma when
// irregular), its fairlead and anchor taken from the last and first stations.
SolverOutput synthetic_dynamic_tension_output(bool irregular,
                                              const std::vector<double>& s_m,
                                              const std::vector<double>& mean_n,
                                              const std::vector<double>& tension_n,
                                              const std::vector<double>& phase_deg,
                                              const std::vector<double>& motion_m,
                                              const std::vector<double>& normal_damping,
                                              const std::vector<double>& tangential_damping,
                                              double period_s,
                                              const std::vector<double>& spectrum_omega_rad_s,
                                              const std::vector<double>& fairlead_spectrum,
                                              const std::vector<double>& anchor_spectrum,
                                              double zero_upcrossing_period_s,
                                              double most_probable_max_n,
                                              int iterations,
                                              double residual,
                                              bool converged) {
  const std::size_t n = s_m.size();
  for (const auto* v : {&mean_n, &tension_n, &motion_m, &normal_damping, &tangential_damping}) {
    if (v->size() != n || n < 2)
      throw InvalidInput("_synthetic_dynamic_tension_output: every profile needs len(s_m) >= 2");
  }
  DynamicTension t;
  t.irregular = irregular;
  t.s_m = vector_of(s_m);
  t.mean_n = vector_of(mean_n);
  (irregular ? t.std_n : t.amplitude_n) = vector_of(tension_n);
  if (!irregular) {
    t.period_s = period_s;
    t.omega_rad_s = 2.0 * M_PI / period_s;
    t.phase_deg = vector_of(phase_deg);
  } else {
    t.spectrum_omega_rad_s = vector_of(spectrum_omega_rad_s);
    t.fairlead_spectrum_n2_s_per_rad = vector_of(fairlead_spectrum);
    t.anchor_spectrum_n2_s_per_rad = vector_of(anchor_spectrum);
  }
  t.motion_m = vector_of(motion_m);
  t.normal_damping_n_s_per_m2 = vector_of(normal_damping);
  t.tangential_damping_n_s_per_m2 = vector_of(tangential_damping);
  t.anchor = synthetic_end(t, 0, zero_upcrossing_period_s, most_probable_max_n);
  t.fairlead = synthetic_end(t, Index(n) - 1, zero_upcrossing_period_s, most_probable_max_n);
  t.iterations = iterations;
  t.residual = residual;
  t.converged = converged;
  t.relative_error_estimate = converged ? residual : -1.0;
  t.diagnostic = converged ? "" : "no fixed point within the iterations (synthetic)";
  SolverOutput output;
  output.solver = "synthetic";
  output.summary.termination = converged ? Termination::Converged : Termination::NoConvergence;
  output.dynamic_tension.push_back(std::move(t));
  return output;
}

}  // namespace

void bind_synthetic_output(py::module_& module) {
  module.def("_synthetic_dynamic_tension_output", &synthetic_dynamic_tension_output,
             py::arg("irregular"), py::arg("s_m"), py::arg("mean_n"), py::arg("tension_n"),
             py::arg("phase_deg"), py::arg("motion_m"), py::arg("normal_damping_n_s_per_m2"),
             py::arg("tangential_damping_n_s_per_m2"), py::arg("period_s") = 0.0,
             py::arg("spectrum_omega_rad_s") = std::vector<double>{},
             py::arg("fairlead_spectrum_n2_s_per_rad") = std::vector<double>{},
             py::arg("anchor_spectrum_n2_s_per_rad") = std::vector<double>{},
             py::arg("zero_upcrossing_period_s") = -1.0, py::arg("most_probable_max_n") = -1.0,
             py::arg("iterations") = 7, py::arg("residual") = 1e-10, py::arg("converged") = true,
             "Tests only: a SolverResult holding one DynamicTension of the given profiles.");
  module.def("_synthetic_damped_output", &synthetic_damped_output, py::arg("eigenvalues"),
             py::arg("s_m"), py::arg("u"), py::arg("w"), py::arg("tension_n"),
             py::arg("overdamped_decay_rates_1_s"), py::arg("forced_omega_rad_s"),
             py::arg("forced_w_m"),
             "Tests only: a SolverResult holding the given damped roots and complex shapes.");
}

}  // namespace catena::python
