// SPDX-License-Identifier: MIT
// The small-strain limit and the knobs shared by the asymptotic and airy solvers (see
// taut_cable_theory.hpp).
#include "solvers/common/taut_cable_theory.hpp"

#include <fmt/format.h>

#include "catena/core/error.hpp"

namespace catena::internal {

double static_strain(const Problem& problem, const DimensionlessGroups& groups) {
  return problem.cable.is_inextensible() ? 0.0 : groups.t0_n / problem.cable.axial_stiffness_n;
}

void require_warning_below_max_eps(const std::string& solver,
                                   double eps_warning_threshold,
                                   double max_eps) {
  if (eps_warning_threshold > max_eps) {
    throw InvalidInput(
        fmt::format("[solvers.{}].eps_warning_threshold = {}: must be <= max_eps = {}", solver,
                    eps_warning_threshold, max_eps));
  }
}

}  // namespace catena::internal
