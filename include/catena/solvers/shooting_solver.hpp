// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `shooting` solver (docs/explanation/methods/shooting.md): the exact linear boundary-value
/// solution of the cable equations, integrated along s by SUNDIALS ARKODE's ERKStep with Verner's
/// 6(5) pair (or SUNDIALS CVODE: knob `method`). It is the project's accuracy reference.
///
/// Model (docs/explanation/physics.md). About the static elastic catenary, harmonic motion D =
/// Phi(s) e^{i w t} satisfies (A Phi')' + w^2 Mmat Phi = 0 with A = EA t t^T + (T/(1+e)) n n^T and
/// Mmat = m t t^T + M n n^T; out of plane ((T/(1+e)) v')' + w^2 M v = 0. The solver integrates the
/// first-order form Phi' = A^{-1} F, F' = -w^2 Mmat Phi, with
/// A^{-1} = t t^T / EA + ((1+e)/T) n n^T, which is finite for EA = inf: an inextensible cable is
/// solved exactly, without a penalty. The coefficients are the closed forms of the shared statics.
///
/// Frequencies. The two principal solutions (Phi(0) = 0, F(0) = unit vectors) are integrated
/// together (8 states in plane, 2 out of plane, plus one phase state); w is a natural frequency
/// when det Phi(L; w) = 0. The number of natural frequencies below a trial w equals the number of
/// conjugate points of the principal solution on (0, L] (Morse index theorem for this self-adjoint
/// Hamiltonian system; out of plane, Sturm's zero count). It is read off the monotone phase
/// theta = arg det(Phi + i F), integrated along s as an extra ODE component, together with the
/// eigen-angles of the unitary matrix (Phi - iF)(Phi + iF)^{-1} at s = L (Atkinson's formulation;
/// out of plane, Pruefer's angle). A zero of det Phi between output points can therefore not be
/// missed, and the count is exact as long as the integrated phase is accurate to better than pi
/// (its mismatch with arg det at s = L is reported as the "phase defect").
///
/// Each mode n is first bracketed by counts: the largest sampled w with count n - 1 and the
/// smallest with count n (new samples by a phase-extrapolated guess or bisection). Inside such a
/// certified bracket det Phi(L) / sqrt(det(Phi^T Phi + F^T F)) -- a smooth function of w in
/// [-1, 1], invariant under the re-orthonormalisation below -- changes sign exactly once, and
/// the root is refined to `root_tolerance` by safeguarded Newton steps, each shot carrying the
/// frequency derivative from the variational equation (Brent's method where a step leaves the
/// bracket or does not shrink, or with `root_finder = "brent"`). Out of plane the continuous count
/// N + (angle - pi)/(2 pi) (Pruefer) is itself smooth and equals n at the n-th eigenvalue, so
/// the refinement works on it directly from any count bracket. Several eigenvalues inside a bracket
/// narrower than the tolerance (an exactly double root, e.g. Irvine's cross-over, where the count
/// jumps by 2) are returned as that many modes at the same frequency; roots closer than
/// 1000 rtol share a joint null space for their shapes, mass-orthogonalised.
///
/// Loss of independence. The in-plane pair can grow at different exponential rates (the "chain"
/// solutions of curved inextensible cables at high frequency, large lambda^2). After every
/// integration step the Gram matrix of the pair is checked; when its condition number exceeds
/// `max_condition` or its scale leaves [1e-6, 1e6], the pair is replaced by the Q of its QR
/// factorisation with positive diagonal R (det R > 0, so the sign of det Phi and the phase are
/// unchanged) and the integration continues from it; the R factors map the final null vector back
/// onto every segment. A compound-matrix (exterior-product) formulation was not used because the
/// shapes and the forced response need the solutions themselves. The variables are also rescaled
/// symplectically (Phi by kappa, F by 1/kappa, kappa^2 = max(Omega, 1)) so that the phase turns at
/// a nearly uniform rate.
///
/// Straight inextensible cable (vertical, H = 0, EA = inf): the axial direction is rigid and
/// det Phi(L) vanishes for every w; the in-plane modes are then the transverse string modes
/// (solved as the scalar problem), with u = 0 and zero dynamic tension (a constant axial tension is
/// statically indeterminate); a forced axial displacement has no finite response (diagnostic).
///
/// Mode shapes: the null vector of Phi(L) combined with the solutions recorded at the request's
/// stations (one step of the method from the step's start, or CVODE's dense output), u = Phi . t, w
/// = Phi . n, tau = t . F, normalised and integrated with the shared mode_tools. Forced response:
/// the principal solutions from the fixed end, combined to meet the prescribed displacement at the
/// driven end (one 2x2 solve per frequency); a frequency where det Phi(L) is at the
/// integration-noise level is reported as resonance, one with |det| < 1e-3 gets a near-resonance
/// warning.
///
/// Error estimate per frequency: half the final root bracket plus the change of the root when the
/// end determinant is re-evaluated at 10x tighter tolerances (one extra shot per mode, one secant
/// step with the slope of the final bracket). Observed: the frequency error is about 0.3-0.5 rtol
/// from rtol = 1e-4 to 1e-12, and the estimate covers it (see the convergence test).
///
/// References: Atkinson, Discrete and Continuous Boundary Problems (1964), ch. 10 (oscillation
/// of Hamiltonian systems); Irvine, Cable Structures (1981); Gale (1976)
/// (docs/reference/references.md).

#include <string>

#include "catena/models/cable.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

/// The integrator of a shot (docs/explanation/methods/shooting.md, "Integrators").
enum class ShootingMethod {
  RungeKutta,  ///< ARKODE's ERKStep (explicit Runge-Kutta), Verner's 6(5) pair (default; "rk")
  Adams,       ///< CVODE's Adams-Moulton, orders 1-12
  Bdf          ///< CVODE's BDF, orders 1-5 (for comparison / stiff variants)
};
/// "rk", "adams", "bdf".
std::string to_string(ShootingMethod method);

/// Options of the shooting solver. Scene knobs: `rtol`, `atol`, `root_tolerance`, `method`,
/// `nonlinear_solver`, `max_steps`, `max_condition`, `error_estimate`, `root_finder`.
struct ShootingSolverOptions {
  /// Relative tolerance of the integration [-] (knob `rtol`). In [1e-14, 1e-2].
  double relative_tolerance = 1e-10;
  /// Absolute tolerance of the integration on the scaled state (displacements in units of L, forces
  /// in units of the largest end tension; the basis has norm ~1) [-] (knob `atol`). 0 means
  /// relative_tolerance / 100. In [0, 1e-2].
  double absolute_tolerance = 0.0;
  /// Relative width of the final root bracket [-] (knob `root_tolerance`). 0 means
  /// relative_tolerance: the end determinant carries integration noise of that order, so a
  /// narrower bracket only costs shots without improving the frequency. In [0, 1e-2].
  double root_tolerance = 0.0;
  /// Integration method (knob `method` = "rk" | "adams" | "bdf").
  ShootingMethod method = ShootingMethod::RungeKutta;
  /// CVODE's nonlinear solver (knob `nonlinear_solver` = "newton" | "fixed_point"): Newton with
  /// the analytic Jacobian and SUNDIALS' dense LU (SUNDenseMatrix + SUNLinSol_Dense; default), or
  /// functional iteration (no Jacobian; the system is not stiff). Both take the same time within
  /// ~10% here (measured: CVODE's per-step vector work dominates); Newton needs ~40% fewer RHS
  /// evaluations.
  bool fixed_point_iteration = false;
  /// Maximum integration steps per shot (knob `max_steps`). >= 100.
  long max_steps = 500000;
  /// Re-orthonormalise the in-plane pair when cond(Gram) exceeds this (knob `max_condition`).
  /// In [2, 1e8].
  double max_condition = 1e2;
  /// Estimate each frequency's integration error by one extra shot at 10x tighter tolerances
  /// (knob `error_estimate`). When false the estimate is the root bracket plus 10 rtol.
  bool error_estimate = true;
  /// Root refinement (knob `root_finder` = "newton" | "brent"): safeguarded Newton steps with
  /// the frequency derivative carried by the shot (the variational equation; Brent's method takes
  /// over where a step leaves the sign bracket or does not shrink), or Brent's method alone. A
  /// general line (several segments or point attachments) and a line starting on the seabed are
  /// refined by Brent either way (measured cheaper there: docs/explanation/methods/shooting.md).
  bool newton = true;

  /// absolute_tolerance with the default applied.
  double effective_absolute_tolerance() const;
  /// root_tolerance with the default applied.
  double effective_root_tolerance() const;
  /// Throws InvalidInput naming the knob (`[solvers.shooting].<knob>`), its value and its range
  /// (the ranges above, declared once in the solver's knob table).
  void validate() const;
};

/// Solves the request (frequencies, shapes, tension, forced response) by shooting.
/// \param problem the cable and supports (validated).
/// \param statics its static solution (solve_statics).
/// \param groups its dimensionless groups (for kL/pi and Gale's ratio).
/// \param request what to compute.
/// \param options integrator and root-finding settings; throws InvalidInput when invalid.
/// \return every quantity asked, with a summary per plane and an overall summary; numerical
/// trouble is reported there (never thrown, never NaN). NotApplicable when the static tension
/// vanishes inside the cable (H = 0 and V changes sign): the equations divide by T.
SolverOutput solve_shooting(const Problem& problem,
                            const StaticSolution& statics,
                            const DimensionlessGroups& groups,
                            const SolveRequest& request,
                            const ShootingSolverOptions& options = {});

}  // namespace catena
