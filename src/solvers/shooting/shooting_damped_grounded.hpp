// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The grounded part of a damped shot (docs/explanation/methods/shooting.md, "Damping on the
/// seabed"): the leading grounded pieces of a line, shot from the anchor A at a complex root
/// lambda, in a form whose cost does not grow with the foundation's stiffness.
///
/// As in the undamped grounded run (shooting_grounded.hpp) the line lies straight along +x, so the
/// damped system falls apart into independent scalar directions d (in plane: axial x, vertical y;
/// out of plane: one), each a complex scalar equation in the scaled physical variables
///
///     phi_d' = b_d F_d,   F_d' = -c_d phi_d,
///     b_x = T_ref / (EA + c_a lambda),  b_y = b_out = T_ref (1 + e) / T(s),
///     c_x = -(L^2/T_ref) (lambda^2 m_t + lambda c_t(s) + k_t),
///     c_y = -(L^2/T_ref) (lambda^2 M + lambda c_n(s) + k_s + c_s lambda),
///     c_out = -(L^2/T_ref) (lambda^2 M + lambda c_n(s) + k_t),
///
/// (the substitutions of damped_coefficients_at, shooting_system.hpp; c_n, c_t include the
/// linearised drag when the shot carries one), and the principal solutions (phi = 0, F = I at A)
/// stay diagonal. The undamped run's Pruefer angle does not carry over: with complex coefficients
/// the angle is complex and its cosine overflows along a damped wave. Instead each column is
/// carried normalised in balanced variables z = (beta phi, F / beta), beta^2 = sqrt(|c_d| / |b_d|)
/// at the run's start, as z = exp(g) y, |y| = 1, g complex, z' = A z with
/// A = [0, beta^2 b_d; -c_d / beta^2, 0]. Each step propagates y by Magnus' fourth-order
/// exponential method (two Gauss points, the exponential of the traceless 2 x 2 in closed form,
/// its growth e^mu put into g) and renormalises it (the norm into g); step-doubling control at
/// rtol (written by hand: no SUNDIALS integrator is exponential), stopping at every piece
/// end and every station of the drag profile (kinks of c(s)): exact for frozen coefficients, so
/// the steps follow only the variation of T(s) and c(s), however stiff the foundation (where it
/// dominates, y sits at the growing eigenvector and g takes the growth and the turning of the
/// phase, exp(i Im g)). Where the wave dominates, y turns at the wave's rate as the undamped
/// columns do. Nothing is counted (the damped roots are counted by the argument principle).

#include <Eigen/Core>
#include <memory>

#include "solvers/shooting/shooting_system.hpp"

namespace catena::internal {

/// The principal solutions at x in the run, per direction d: the unit column (phi_d, F_d) in the
/// scaled physical variables times exp(log_scale_d) (complex: its imaginary part is a phase).
struct DampedGroundedFrame {
  Eigen::VectorXcd phi;
  Eigen::VectorXcd force;
  Eigen::VectorXcd log_scale;
};

/// The complex direction coefficients b_d, c_d (header) of the current piece data.piece at s [m]
/// for the root data.lambda, with the pieces' damping and data's drag.
void damped_grounded_coefficients(const RhsData& data,
                                  double s,
                                  std::complex<double>* b,
                                  std::complex<double>* c);

/// Integrates the grounded run of one damped shot (from A) on the normalised columns (header).
/// Reads the coefficients, lambda, the damping and the drag from `data` at every call, so the owner
/// may change them between shots; data.piece is moved along the run.
class DampedGroundedRun {
 public:
  /// `data` outlives the run; `pieces` the run length (grounded_run_length).
  DampedGroundedRun(RhsData& data, std::size_t pieces, long max_steps);
  ~DampedGroundedRun();
  DampedGroundedRun(const DampedGroundedRun&) = delete;
  DampedGroundedRun& operator=(const DampedGroundedRun&) = delete;

  /// x = s / L at the end of the run.
  double end_x() const;
  /// The run's pieces (the next piece is the first the general shot takes).
  std::size_t pieces() const;
  /// Starts a shot at x = 0 (phi = 0, F = I) at data.lambda with the relative tolerance (the
  /// columns are unit vectors: the absolute one is not used).
  void begin(double relative_tolerance, double absolute_tolerance);
  /// Integrates on to x (non-decreasing, at most end_x()) and returns the frame there.
  /// Throws ShootingFailure beyond max_steps or on a non-finite step.
  DampedGroundedFrame advance_to(double x);
  /// Accepted and rejected steps and coefficient evaluations of the current shot.
  long steps() const;
  long rhs_evaluations() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::internal
