// SPDX-License-Identifier: MIT
// Damping of the dimensionless problem forms from Python: the same conversions as the scene reader
// (set_taut_inclined_damping, set_gale_damping in catena/statics/problem_builders.hpp), with the
// nondimensional coefficients named as the caller spelt them.
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
  set_taut_inclined_damping(problem, eta);
  return problem;
}

Problem with_gale_damping(Problem problem, double eta1, double eta2) {
  require_eta(eta1, problem.form == ProblemForm::GaleXi ? "gale_xi" : "gale_sag", "eta1");
  require_eta(eta2, problem.form == ProblemForm::GaleXi ? "gale_xi" : "gale_sag", "eta2");
  set_gale_damping(problem, eta1, eta2);
  return problem;
}

}  // namespace catena::python
