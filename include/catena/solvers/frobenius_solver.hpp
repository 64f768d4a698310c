#pragma once
/// \file
/// The `frobenius` solver (DESIGN.md §2.3): Gale's power-series solution of the inextensible
/// catenary (seed 003, Gale 1976, sec. II.4), extended.
///
/// Model: EA = inf (inextensible), so the tangential strain of the motion vanishes. In Gale's
/// variables (a = H/W0, sigma = (s - s_apex)/a, xi = sign(sigma)(sqrt(1+sigma^2) - 1),
/// Omega = w / sqrt(g/a), g = W0/m, mu = M/m) the tangential displacement U obeys the fourth-order
/// eq. 2.42 in |xi| (exponents 0, 1/2, 1, 3/2 at the apex xi = 0), the normal displacement is
/// V = (1+sigma^2) dU/dsigma (2.36) and the dynamic tension T (2.37); out of plane the displacement
/// obeys eq. 2.44 (exponents 0, 1/2). The equations were re-derived from DESIGN.md §1.3 (see
/// verification/tools/frobenius_derive_odes.py), not copied from the OCR.
///
/// Method: a general Frobenius engine builds the series from the coefficient polynomials; the
/// expansion about the apex is continued by Taylor expansions about ordinary points (each within
/// `step_ratio` of its radius of convergence), so any |xi| is reachable (the thesis stops at
/// |xi| < 4). The number of terms follows `tolerance`. Frequencies are the roots of the boundary
/// determinant (U = V = 0 at both ends in plane, 4x4; v = 0 out of plane, 2x2), bracketed on a grid
/// in Omega a tenth of the asymptotic mode spacing apart, with every local minimum of |det| between
/// sign changes searched for a hidden close pair, then refined by bisection/secant. Each root is
/// re-checked in long double (and quad precision when long double and double disagree by more than
/// the tolerance); the difference is part of the reported error estimate, together with the
/// truncation estimate propagated through the determinant.

#include "catena/models/cable.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

/// Options of the frobenius solver.
struct FrobeniusSolverOptions {
  /// Target relative accuracy of each frequency [-], in [1e-15, 1e-3]. Sets the series length
  /// (terms are added until the tail is below tolerance * 1e-3 of the largest term) and the root
  /// refinement.
  double tolerance = 1e-12;
  /// Cap on the number of terms of any one expansion, in [8, 5000]. When it binds the result is
  /// flagged NoConvergence.
  int max_terms = 600;
  /// Distance between successive expansion centres as a fraction of the radius of convergence of
  /// the current expansion, in [0.1, 0.8]. Smaller: more centres, fewer terms each.
  double step_ratio = 0.5;
  /// Grid spacing of the root scan as a fraction of the asymptotic mode spacing, in [0.01, 0.5].
  double scan_fraction = 0.1;
  /// Allow the precision ladder (long double, then 113-bit quad) when double is not enough.
  bool extended_precision = true;

  /// Throws InvalidInput naming the field and the violated range.
  void validate() const;
};

/// Solves `request` for an inextensible catenary. Returns NotApplicable (with the reason) for an
/// extensible cable or one without an apex parameterization (H = 0). Never throws for numerical
/// trouble; throws InvalidInput for bad options.
SolverOutput solve_frobenius(const Problem& problem, const StaticSolution& statics,
                             const DimensionlessGroups& groups, const SolveRequest& request,
                             const FrobeniusSolverOptions& options = {});

/// The reason the solver does not apply to `problem`, or an empty string when it does.
std::string frobenius_not_applicable_reason(const Problem& problem, const DimensionlessGroups& groups);

}  // namespace catena
