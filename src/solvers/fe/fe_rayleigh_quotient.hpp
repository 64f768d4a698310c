// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The eigenvalue of a computed `fe` mode as its Rayleigh quotient, evaluated element by element
/// (docs/explanation/methods/fe.md, "Rounding"), with a bound on that evaluation's rounding error.
///
/// Why. A stiff chain (EA/T large, a fine mesh) has ||K|| / lambda ~ (EA/T) (N / pi n)^2, so any
/// evaluation that forms K phi first (the Lanczos and Rayleigh-Ritz products) carries a rounding
/// error of eps ||K|| ||phi||^2, i.e. a relative error up to eps (EA/T) (N / pi n)^2 in lambda (the
/// "normwise floor"). The quotient
///
///     lambda = [sum_e (EA_e/l_e) (t_e . d_e)^2 + (T_e/l'_e) (n_e . d_e)^2 + foundation] / phi^T M
///     phi,
///
/// with d_e = phi_{e+1} - phi_e, adds positive terms only. The element differences d_e carry an
/// absolute error of at most u (|phi_{e+1}| + |phi_e|) (u = eps / 2), and each strain term
/// k (t . d)^2 then errs by at most 2 k |t . d| u sqrt(2) (|phi_{e+1}| + |phi_e|); by
/// Cauchy-Schwarz the sum errs by at most 4 sqrt(2) u sqrt(E k_max) ||phi||, E = the quotient's
/// numerator. Relative to E:
///
///     |delta lambda| / lambda <= 2 sqrt(2) eps sqrt(k_max ||phi||^2 / E) + (sums: long double),
///
/// about 4 sqrt(eps x normwise floor): the geometric mean of eps and the normwise floor (1e-10
/// where the floor is 1e-4). The quotient is stationary at the eigenvector, so the vector's own
/// error enters at second order; what the rounding of a backward-stable solve leaves in the
/// vector lies along the stiff axial modes, whose share of the quotient is second order in
/// eps (EA/T) as well (docs/explanation/methods/fe.md, "Rounding", with the suite's check of the
/// estimate).

#include <Eigen/Core>

#include "catena/core/types.hpp"
#include "solvers/fe/fe_chain_statics.hpp"
#include "solvers/fe/fe_operators.hpp"

namespace catena::internal {

/// A mode's eigenvalue lambda = omega^2 [rad^2/s^2] from its vector, and the bound on the
/// relative rounding error of that evaluation (header).
struct RayleighQuotient {
  double value = 0.0;
  double relative_rounding = 0.0;
};

/// The Rayleigh quotient of `phi` (the free unknowns of `chain` in `plane`, as assemble numbers
/// them) with the stiffness evaluated element by element and the mass matrix `mass`.
RayleighQuotient element_rayleigh_quotient(const FeChain& chain,
                                           Plane plane,
                                           const Vector& phi,
                                           const SparseMatrix& mass);

/// Rayleigh-Ritz on the span of `vectors` (columns) with the projected stiffness evaluated element
/// by element, V^T K V = sum_e k_e (t_e . d_e)(t_e . d_e)^T + ..., so that it carries the
/// quotient's structured rounding, not eps ||K||: a computed Ritz vector's components along the
/// other modes, which a projection formed from K V leaves at about eps ||K|| / gap, come out right
/// (docs/explanation/methods/fe.md, "Rounding"). Rotates `vectors` in place to the Ritz vectors,
/// ascending; false (vectors unchanged) when the small eigenproblem fails.
bool element_rayleigh_ritz(const FeChain& chain,
                           Plane plane,
                           Eigen::MatrixXd& vectors,
                           const SparseMatrix& mass);

}  // namespace catena::internal
