// SPDX-License-Identifier: MIT
// Damping of the dimensionless problem forms from Python. The conversions repeat those of the scene
// reader (src/io/scene_reader.cpp, read_taut_inclined and read_gale), whose helpers are private to
// it; python/tests/test_damping.py checks that both give the same coefficients, bit for bit.
#include "damping.hpp"

#include <fmt/format.h>

#include <cmath>

#include "catena/core/error.hpp"
#include "catena/statics/problem_builders.hpp"

namespace catena::python {
namespace {

// A nondimensional damping coefficient, named as the caller spelt it: a negative or non-finite one
// would otherwise surface as the physical coefficient it scales to, which the caller did not give.
void require_eta(double value, const char* form, const char* name) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidInput(
        fmt::format("Invalid Problem.{}: {} = {}: must be finite and >= 0 [-]", form, name, value));
  }
}

}  // namespace

Problem damped_taut_inclined_problem(
    double eps, double phi_deg, double lambda2, double mass_ratio, const SectionDamping& eta) {
  require_eta(eta.tangential_n_s_per_m2, "taut_inclined", "eta_tangential");
  require_eta(eta.normal_n_s_per_m2, "taut_inclined", "eta_normal");
  require_eta(eta.axial_n_s, "taut_inclined", "eta_axial");
  Problem problem = make_taut_inclined_problem(eps, phi_deg, lambda2, mass_ratio);
  // The builder's T0 = 1 N (problem_builders.hpp), its M and its L.
  const double t0_n = 1.0;
  const double length = problem.cable.length_m;
  const double impedance = std::sqrt(t0_n * problem.cable.normal_mass_kg_per_m());
  problem.cable.damping.tangential_n_s_per_m2 = eta.tangential_n_s_per_m2 * impedance / length;
  problem.cable.damping.normal_n_s_per_m2 = eta.normal_n_s_per_m2 * impedance / length;
  problem.cable.damping.axial_n_s = eta.axial_n_s * impedance * length;
  problem.validate();  // e.g. a coefficient beyond the magnitude bounds
  return problem;
}

Problem with_gale_damping(Problem problem, double eta1, double eta2) {
  require_eta(eta1, problem.form == ProblemForm::GaleXi ? "gale_xi" : "gale_sag", "eta1");
  require_eta(eta2, problem.form == ProblemForm::GaleXi ? "gale_xi" : "gale_sag", "eta2");
  // sqrt(g / a) rho with rho = m, g = W0 / m, a = H / W0 from the builder's values.
  const CableProperties& c = problem.cable;
  const double horizontal =
      problem.prescribed_forces ? problem.prescribed_forces->horizontal_n : c.weight_n_per_m;
  const double g = c.weight_n_per_m / c.mass_kg_per_m;
  const double a = horizontal / c.weight_n_per_m;
  const double scale = c.mass_kg_per_m * std::sqrt(g / a);
  problem.cable.damping.tangential_n_s_per_m2 = eta1 * scale;
  problem.cable.damping.normal_n_s_per_m2 = eta2 * scale;
  problem.validate();
  return problem;
}

}  // namespace catena::python
