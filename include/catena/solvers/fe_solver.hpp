// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `fe` solver (docs/explanation/methods/fe.md): the cable as a chain of N two-node axial bar
/// elements with lumped nodal masses, linearised about the chain's own exact static equilibrium,
/// and solved as the sparse generalized eigenproblem K phi = omega^2 Mmat phi.
///
/// Discrete statics. The unstretched length L is cut into N elements of length l0 = L/N; the weight
/// W0 l0 of each element is lumped half on each of its two nodes, so interior nodes carry W0 l0 and
/// the two end nodes W0 l0 / 2, which goes straight into the supports. With (H, V_A) the force the
/// support a exerts along the cable (the same unknowns and sign convention as the continuous
/// statics, F(s) = (H, V_A + W0 s) is the force on the part beyond s), element j = 0..N-1 carries
///
///     F_j = (H, V_A + W0 l0 (j + 1/2)),   T_j = |F_j|,   t_j = F_j / T_j,
///
/// i.e. exactly the continuous force at the element midpoint, and its stretched length is
/// l_j = l0 (1 + T_j/EA) along t_j. (H, V_A) solve sum_j l_j t_j = B - A by a 2x2 Newton iteration
/// (analytic Jacobian sum_j l0 [(I - t_j t_j^T)/T_j + I/EA]) started from the shared continuous
/// statics. A problem given by its end forces (Problem::prescribed_forces: taut and Gale forms)
/// keeps those forces; the chain's end then differs from b by O(l0^2), which is part of the
/// discretisation error that Richardson extrapolation removes.
///
/// Dynamics. Element tangent stiffness k_j = (EA/l0) t_j t_j^T + (T_j/l_j)(I - t_j t_j^T)
/// (docs/explanation/physics.md, A = EA t t^T + T/(1+e) n n^T, integrated over one element); lumped
/// node masses l0 (m t_i t_i^T + M n_i n_i^T), with the node tangent t_i the bisector of the two
/// adjacent element tangents; the fixed end nodes are removed. In plane: 2 (N-1) unknowns, block
/// tridiagonal. Out of plane: k_j = T_j / l_j, node mass M l0: N-1 unknowns, tridiagonal.
///
/// Eigenpairs. With the lumped mass factored blockwise, Mmat = L L^T (2x2 blocks), the problem is
/// the standard symmetric one A y = lambda y, A = L^{-1} K L^{-T}, phi = L^{-T} y. Spectra's
/// SymEigsSolver (implicitly restarted Lanczos) runs on its shift-invert operator (shift 0: the
/// lowest modes; sorted lowest first), applying (A - sigma I)^{-1} = L^T (K - sigma Mmat)^{-1} L
/// through a banded LDL^T of K - sigma Mmat (half bandwidth 3 in plane, 1 out of plane: O(N) to
/// factor and to solve). The standard form avoids the Mmat-inner products of Spectra's generalized
/// solver, which cost more than the banded solves here. The Ritz pairs are then polished by at most
/// two steps of inverse subspace iteration with Rayleigh-Ritz, until the normwise backward error
/// ||K phi - lambda Mmat phi|| / ((||K|| + lambda ||Mmat||) ||phi||) is at rounding level (the
/// relative residual ||K phi - lambda Mmat phi|| / ||K phi|| of a stiff chain cannot go below about
/// eps ||K|| / ||K phi|| ~ 1e-16 (EA/T)(2N/(pi n))^2, and is reported as it is). A singular shift
/// is moved below the spectrum and the move is reported; problems of at most 64 unknowns are
/// solved densely. Mode count proof: Sylvester's law of inertia: the number of negative pivots of
/// LDL^T(K - sigma_top Mmat), sigma_top a relative max(1e-9, 10 residual) above the highest
/// returned eigenvalue, is the number of eigenvalues below sigma_top; it must equal the number of
/// modes returned (ModalResult::proved_count_below_top), on every mesh.
///
/// Error. Lumped-mass bar chains converge as O(l0^2). With Richardson extrapolation (default) the
/// problem is solved with N and 2N elements and omega = omega_2N + (omega_2N - omega_N)/3 (order
/// 4); the error estimate of each frequency is |omega - omega_2N|, the size of the correction: an
/// upper estimate, since the extrapolated value is much closer than the unextrapolated one (for the
/// taut string, estimate 1e-5 for an actual error below 1e-9 at N = 1000, mode 10). Modes are
/// paired across meshes (and penalties) by their shapes (largest MAC on the common nodes), not by
/// rank: near a cross-over two close modes may swap order between meshes. The extrapolated modes
/// are reported lowest first.
///
/// Inextensible cables (EA = inf). A finite penalty EA = H / kappa is used, with two values
/// kappa and 2 kappa and a linear extrapolation to kappa = 0 (the frequencies depend on the
/// extensibility through Irvine's 1/lambda^2, which is linear in kappa); the summary says so.
/// Measured on Gale's catenaries at N = 800: the extrapolated frequencies change by ~1e-8..1e-7
/// relative between kappa = 1e-5 and 1e-6; below 1e-6 the rounding of the stiff penalty grows
/// (~1e-6 relative at kappa = 1e-7). So the penalty limits inextensible results to a few 1e-7
/// relative (seen as changes of that size when only the order of floating-point operations
/// changes).
///
/// Shapes, tension, forced response. Nodal displacements are interpolated linearly to the request
/// stations and projected on the continuous static tangent and normal there (the shared statics);
/// dynamic tension per element tau_j = EA t_j . (D_{j+1} - D_j) / l0 (the penalty EA for an
/// inextensible cable), interpolated linearly between element midpoints. A harmonic end
/// displacement d is imposed by one sparse solve of (K - omega^2 Mmat) x = -K_ib d per forcing
/// frequency; a forcing frequency at a natural frequency (within the frequency's own error
/// estimate) gets a diagnostic instead of a response.
///
/// Everything that is not bad input is reported in the summaries, never thrown: a chain too stiff
/// for double precision in plane (rounding floor of mode 1 above 1e-2) is declined as
/// no-convergence before any eigen solve, and a discrete statics that does not close (or a slack
/// element) is a numerical failure.
///
/// Code: the stages are in src/solvers/fe/fe_*: discrete statics (fe_chain_statics),
/// operators (fe_operators), the eigenpairs of one (mesh, penalty) level (fe_eigen), the plan and
/// its levels (fe_levels), stations (fe_shapes), extrapolation (fe_extrapolation), forced response
/// (fe_forced) and summary text (fe_summary); fe_solver.cpp runs them through the solver skeleton.

#include "catena/models/cable.hpp"
#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solve_request.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

/// Options of the `fe` solver. Scene knobs: `elements`, `richardson`, `kappa`, `observed_order`,
/// `tolerance`, `max_elements`; `eigen_tolerance` and `max_restarts` are set through this struct
/// only.
struct FeSolverOptions {
  /// Number of bar elements N (the coarse mesh when Richardson is on). In [2, 5e7]; the coarsest
  /// mesh used resolves at most N / 2 modes per plane (docs/explanation/methods/fe.md), more is
  /// InvalidInput; at the default 400, a request of more than 200 modes per plane raises N to
  /// 2 x modes (rounded up to a multiple of 4) instead. The discretisation error of mode n is about
  /// (n pi / 2N)^2 / 6 relative without Richardson.
  int elements = 400;
  /// Solve with N and 2N elements and extrapolate (order 2 -> 4). Without it, the error estimate
  /// needs a second mesh anyway, so N/2 is solved as well (when N >= 4) for the estimate only.
  bool richardson = true;
  /// Also solve 4N elements and report the observed convergence order of the unextrapolated
  /// frequencies, p = log2((omega_N - omega_2N) / (omega_2N - omega_4N)), in the notes.
  bool observed_order = false;
  /// Inextensible cables only: penalty kappa = H / EA [-], in (0, 1e-2]. The extrapolation in kappa
  /// uses kappa and 2 kappa. The penalty error is O(kappa) before and O(kappa^2) after the
  /// extrapolation, while the rounding error of the stiff axial springs grows like 1/kappa: on
  /// Gale's catenaries (N = 800) the extrapolated frequencies at kappa = 1e-6 agree with those at
  /// 1e-5 to ~1e-7 relative, and at 1e-7 rounding reaches ~1e-6. Hence the default 1e-6.
  double kappa = 1e-6;
  /// Accuracy target of each frequency [-], in [0, 1]; 0: none. When a mode's error estimate
  /// exceeds it, fe solves again on a finer mesh (N predicted from the estimates' order, at most
  /// max_elements; docs/explanation/methods/fe.md, "Meeting a tolerance"); a mode that still
  /// exceeds it is listed in the plane's SolverSummary::missed_modes and the plane is
  /// NoConvergence. The default 1e-6 is the accuracy fe is declared to reach (its registry
  /// entry's accuracy_target, which the harness holds its frequencies to): until 2026-12 the
  /// default was 0, and a default solve returned "converged" modes with estimates up to 3e-5 that
  /// the checks then held to 1e-6 (docs/reference/verdicts.md, "Default verdicts").
  double tolerance = 1e-6;
  /// The largest N a tolerance may refine to, in [2, 5e7]. At or below `elements`: no refinement.
  int max_elements = 51200;
  /// Spectra convergence tolerance on the Ritz values of the shift-inverted operator (relative).
  /// In (0, 1e-4].
  double eigen_tolerance = 1e-13;
  /// Spectra restarts before giving up. >= 1.
  int max_restarts = 1000;

  /// Throws InvalidInput naming the field, its value and the violated constraint.
  void validate() const;
};

/// Solves the request (in-plane and/or out-of-plane modes, shapes, tension, forced response) by
/// the lumped-mass chain described above.
/// \param problem the cable and supports (validated here).
/// \param statics the shared continuous statics: the initial guess of the discrete statics and the
///        tangent/normal on which shapes are projected.
/// \param groups frequency conversions (kL/pi, Gale's ratio).
/// \param request what to compute.
/// \param options discretisation and solver options.
/// \throws InvalidInput for bad options, a bad request or too many modes for N.
SolverOutput solve_fe(const Problem& problem,
                      const StaticSolution& statics,
                      const DimensionlessGroups& groups,
                      const SolveRequest& request,
                      const FeSolverOptions& options = {});

}  // namespace catena
