// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `frobenius` solver (docs/explanation/methods/frobenius.md): Gale's power-series solution of
/// the inextensible catenary (Gale 1976, sec. II.4; docs/reference/references.md), extended.
///
/// Model: EA = inf (inextensible), so the tangential strain of the motion vanishes. In Gale's
/// variables (a = H/W0, sigma = (s - s_apex)/a, xi = sign(sigma)(sqrt(1+sigma^2) - 1),
/// Omega = w / sqrt(g/a), g = W0/m, mu = M/m) the tangential displacement U obeys the fourth-order
/// eq. 2.42 in |xi| (exponents 0, 1/2, 1, 3/2 at the apex xi = 0), the normal displacement is
/// V = (1+sigma^2) dU/dsigma (2.36) and the dynamic tension T (2.37); out of plane the displacement
/// obeys eq. 2.44 (exponents 0, 1/2). The equations were re-derived from the model of
/// docs/explanation/physics.md (see verification/tools/frobenius_derive_odes.py), not copied from
/// the OCR.
///
/// Method: a general Frobenius engine builds the series from the coefficient polynomials; the
/// expansion about the apex is continued by Taylor expansions about ordinary points, matched where
/// both converge (each point at `step_ratio` of the radius of convergence of the expansion used),
/// so any |xi| is reachable (the thesis stops at |xi| < 4). The number of terms follows
/// `tolerance` (capped by `max_terms`). Frequencies are the roots of the boundary determinant
/// (U = V = 0 at both ends in plane, 4x4; v = 0 out of plane, 2x2), columns scaled by a smooth
/// positive norm so that the scaled determinant keeps its sign and zeros:
///  - bracketed on a grid in Omega `scan_fraction` of the asymptotic mode spacing apart (WKB:
///    pi / int sqrt(mu/C) dsigma), every local minimum of |det| between sign changes searched by
///    golden section for a hidden close pair, then refined (Illinois regula falsi);
///  - the count is checked independently: out of plane by Sturm oscillation (mode n has n - 1
///    interior nodes), in plane by the conjugate points of the clamped end (Morse index: the zeros
///    of det[U, V] of the two solutions clamped at xi1, counted along the cable just above the
///    highest root; a disagreement triggers a finer rescan); `proved_count_below_top` is set when
///    the count agrees;
///  - each root is corrected a posteriori by secant-Newton steps with series cut 1e-3 finer per
///    step and evaluated in long double (quad from the third step); the last correction is the
///    reported `relative_error_estimate` (it covers truncation carried through the matched
///    expansions and rounding). The scan itself runs in long double or quad when the largest
///    series term exceeds the sum by more than 1e8 (double) / 1e11 (long double).
/// Modes: null vector of the boundary matrix, U, V and T at the request stations (converted from
/// s through sigma = V(s)/H), normalised by mode_tools. Forced response: the fixed end clamped, the
/// driven end given its displacement (tangential, normal, a given in-plane vector resolved on t and
/// n, or out of plane), U, V, T along the cable (Gale 2.76-2.79).

#include <optional>
#include <string>

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
  /// Close pairs inside one cell are searched at local minima of |det|; in plane, a conjugate-point
  /// count that disagrees with the roots found triggers a rescan 4x finer (twice at most).
  double scan_fraction = 0.2;
  /// Allow the precision ladder (long double, then 113-bit quad) when double is not enough.
  bool extended_precision = true;

  /// Throws InvalidInput naming the knob (`[solvers.frobenius].<knob>`) and its valid range.
  void validate() const;
};

/// Solves `request` for an inextensible catenary. Returns NotApplicable (with the reason) for an
/// extensible cable or one without an apex parameterization (H = 0). Never throws for numerical
/// trouble (it is a status in the summaries); throws InvalidInput for bad options or request.
SolverOutput solve_frobenius(const Problem& problem,
                             const StaticSolution& statics,
                             const DimensionlessGroups& groups,
                             const SolveRequest& request,
                             const FrobeniusSolverOptions& options = {});

/// nullopt when the solver applies to `problem`; otherwise why not.
std::optional<std::string> frobenius_not_applicable_reason(const Problem& problem,
                                                           const DimensionlessGroups& groups);

}  // namespace catena
