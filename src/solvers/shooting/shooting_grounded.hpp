// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The grounded part of a shot (docs/explanation/methods/shooting.md, "Seabed contact: the grounded
/// run"): the leading pieces of a line resting on the seabed, shot from the anchor A, integrated in
/// a form whose cost does not grow with the foundation's stiffness.
///
/// On the seabed the cable is straight along +x, so the scaled system (shooting_integrator.hpp)
/// falls apart into independent scalar directions d (in plane: axial x, then vertical y; out of
/// plane: one), each
///
///     phi_d' = b_d(x) F_d,   F_d' = -c_d phi_d,
///     b_x = T_ref / EA,  b_y = b_out = T_ref (1 + e) / T(s),
///     c_x = Omega^2 m / M_ref - L^2 k_t / T_ref,  c_y = Omega^2 M / M_ref - L^2 k_s / T_ref,
///     c_out = Omega^2 M / M_ref - L^2 k_t / T_ref,
///
/// and the principal solutions (phi = 0, F = I at A) stay diagonal: column d is direction d alone.
/// Each column is carried as a balanced Pruefer pair: with phi_d = rho cos(psi) / beta,
/// F_d = beta rho sin(psi), beta^2 = sqrt(|c_d| / b_d) (at the run's start),
///
///     psi' = -c~ cos^2 psi - b~ sin^2 psi,   (ln rho)' = (b~ - c~) sin psi cos psi,
///     b~ = beta^2 b_d,  c~ = c_d / beta^2.
///
/// Where the foundation dominates (c_d < 0) the solution grows like exp(sqrt(b_d |c_d|) x) and psi
/// settles on the attractor where phi and F grow together; the pair is smooth on the scale of the
/// coefficients (the friction profile), so CVODE's BDF takes a few dozen steps however many
/// e-folds the growth spans, where the Adams shot of the 2D x D basis needed a step (and a
/// re-orthonormalisation every 2.3 e-folds) per e-fold. Where c_d > 0 psi turns at the uniform rate
/// sqrt(b_d c_d). The count is kept exact: the conjugate points on (0, x] are the zeros of
/// det Phi = prod_d phi_d, i.e. of each phi_d, counted from its continuous psi by Pruefer's rule
/// (count_conjugate_points with D = 1), and each zero is one-way because b_d > 0.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "solvers/shooting/shooting_coefficients.hpp"

namespace catena::internal {

/// Most e-folds L_g sqrt(k / T) of the foundation's growing solution over one grounded stretch
/// that a shot carries. The integrators keep the grounded columns finite by splitting their growth
/// into factors of at most e^600, stored per shot: 1e8 e-folds is 170 000 factors, a few MB and
/// milliseconds per shot. k_s = 1e24 N/m per m on a chain (1e12 e-folds) stored 2e9 of them,
/// 24 GB, between two checks of the time limit (issue 32). A foundation this stiff holds the
/// grounded part clamped long before: k_s = 3e6 is about 2e3 e-folds on a 400 m chain.
inline constexpr double kMaxGroundedEfolds = 1e8;

/// The principal solutions at x in the run, in the scaled physical variables, per direction d:
/// the unit column (phi_d, F_d) times exp(log_scale_d), and the conjugate points on (0, x].
struct GroundedFrame {
  Eigen::VectorXd phi;
  Eigen::VectorXd force;
  Eigen::VectorXd log_scale;
  int count = 0;
};

/// The direction coefficients of one grounded piece at s (header): b_d and c_d for the scaled
/// Omega^2 `omega2`; `dimension` 2 (x, y) or 1 (out of plane).
void grounded_coefficients(const ShootingCoefficients& k,
                           const ShootingPiece& p,
                           int dimension,
                           double omega2,
                           double s,
                           double* b,
                           double* c);

/// The number of leading pieces the grounded run takes: the grounded pieces from A, none when a
/// point attachment lies on or at the end of them (its jump couples nothing, but it is left to the
/// general shot), or when a direction has no compliance (an inextensible axial direction, b = 0).
std::size_t grounded_run_length(const ShootingCoefficients& k, int dimension);

/// Integrates the grounded run of one shot (from A) with CVODE's BDF on the Pruefer pairs.
class GroundedRun {
 public:
  /// `k` with its pieces filled (ShootingCoefficients::all_pieces()); `pieces` the run length.
  GroundedRun(const ShootingCoefficients& k, int dimension, std::size_t pieces, long max_steps);
  ~GroundedRun();
  GroundedRun(const GroundedRun&) = delete;
  GroundedRun& operator=(const GroundedRun&) = delete;

  /// x = s / L at the end of the run.
  double end_x() const;
  /// The run's pieces (the next piece is the first the general shot takes).
  std::size_t pieces() const;
  /// Starts a shot at x = 0 (phi = 0, F = I) for scaled Omega^2 and the tolerances.
  void begin(double omega2, double relative_tolerance, double absolute_tolerance);
  /// Integrates on to x (non-decreasing, at most end_x()) and returns the frame there.
  /// Throws ShootingFailure when CVODE fails.
  GroundedFrame advance_to(double x);
  /// CVODE steps and RHS evaluations of the current shot.
  long steps() const;
  long rhs_evaluations() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::internal
