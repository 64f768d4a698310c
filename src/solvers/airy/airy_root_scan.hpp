// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The roots kL of the Airy boundary determinant (docs/explanation/methods/airy.md): a scan in kL
/// from a cutoff above the model's spurious low root, with a sign change refined by TOMS 748 and
/// every grid minimum of |det| searched (Brent) for a hidden close pair of roots, as near
/// cross-over. The scan proves no count: the solver cross-checks it with eq. (21).

#include <vector>

#include "catena/solvers/airy_solver.hpp"
#include "solvers/airy/airy_model.hpp"
#include "solvers/common/work_meter.hpp"

namespace catena::internal {

/// What a scan found, and how.
struct AiryRootScan {
  std::vector<double> roots;  ///< kL, ascending, at most the count asked
  long evaluations = 0;       ///< determinant evaluations
  int sign_changes = 0;       ///< roots found between samples of opposite sign (or at a zero)
  int pairs_from_minima = 0;  ///< close pairs found at grid minima of |det|
  double cutoff_kl = 0.0;     ///< the scan starts here: roots below are the spurious one
  double limit_kl = 0.0;      ///< the scan gives up here
};

/// cutoff_fraction times a rigorous lower bound of the first in-plane kL of the full model
/// (Rayleigh with A >= T/(1+e) I and Mmat <= M I: the string of the smallest tension),
/// pi sqrt(min_s(T/(1+e)) / T0).
double spurious_root_cutoff_k_l(const AiryModel& model,
                                const StaticSolution& statics,
                                const DimensionlessGroups& groups,
                                double cutoff_fraction);

/// The lowest `count` roots above the cutoff (options: cutoff_fraction, scan_step_k_l_over_pi,
/// max_k_l_over_pi, tolerance_bits). A `meter` is told the roots found every kStepsPerCheck
/// steps and may stop the scan early (the roots below the point reached).
AiryRootScan scan_airy_roots(const AiryModel& model,
                             const DimensionlessGroups& groups,
                             const StaticSolution& statics,
                             int count,
                             const AirySolverOptions& options,
                             WorkMeter* meter = nullptr);

}  // namespace catena::internal
