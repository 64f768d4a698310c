// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The damped shot of the `shooting` solver (docs/explanation/methods/shooting.md, "Damping"): the
/// principal solutions of the damped equations at a complex characteristic root lambda, the motion
/// ~ e^{lambda t}. The system is the undamped one with the substitutions of
/// docs/explanation/physics.md, "Damping" (damped_coefficients_at in shooting_system.hpp), in the
/// same scaled, balanced, axial-frame variables; its complex basis Y = [Phi; F] (2D x D) is
/// integrated as a real state of twice the size by the same SUNDIALS stepper as the undamped shot
/// (make_damped_stepper). It starts at Phi^ = 0, F^ = I, so that
///
///     D(lambda) = det Phi^(L)
///
/// is an analytic function of lambda whose zeros are the characteristic roots. The columns are
/// re-orthonormalised as in the undamped shot (cond(Y^H Y) > max_condition or the scale leaving
/// [1e-6, 1e6]), with a complex QR whose R has a real positive diagonal: the factors det R > 0
/// are kept as log_scale, so D = determinant * exp(log_scale) with arg D = arg determinant.
/// General lines: pieces and point attachments (whose jump of the internal force carries lambda^2
/// and no damping). A line resting on the seabed, shot from A, starts with the damped grounded run
/// (shooting_damped_grounded.hpp), whose cost does not grow with the foundation's stiffness; shot
/// from b, the general stepper crosses the grounded pieces. A shot may carry linearised drag
/// (set_drag), added to the pieces' damping.

#include <Eigen/Core>
#include <complex>
#include <memory>
#include <vector>

#include "catena/solvers/shooting_solver.hpp"
#include "solvers/common/drag_profile.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_integrator.hpp"

namespace catena::internal {

/// Result of one damped shot.
struct DampedShot {
  std::complex<double> lambda = 0.0;  ///< [1/s]
  /// D(lambda) = determinant * exp(log_scale) (header); arg D = arg determinant.
  std::complex<double> determinant = 0.0;
  double log_scale = 0.0;
  /// Physical [Phi^; F^] at the far end (after the last R factor).
  Eigen::MatrixXcd y_end;
  /// Stations (when asked): the physical basis there and the segment it belongs to.
  std::vector<Eigen::MatrixXcd> station_y;
  std::vector<int> station_segment;
  std::vector<Eigen::MatrixXcd> segment_r;
  long steps = 0;
  long rhs_evaluations = 0;
};

/// Integrates damped principal solutions for one plane; holds the stepper between shots.
class DampedShootingIntegrator {
 public:
  /// Throws ShootingFailure when the SUNDIALS objects cannot be made.
  DampedShootingIntegrator(Plane plane,
                           const ShootingCoefficients& coefficients,
                           const IntegratorSettings& settings);
  ~DampedShootingIntegrator();
  DampedShootingIntegrator(const DampedShootingIntegrator&) = delete;
  DampedShootingIntegrator& operator=(const DampedShootingIntegrator&) = delete;

  /// Multiplies every damping coefficient of the line by `scale` (the homotopy of
  /// shooting_damped_roots.hpp: 0 is the undamped line, 1 the line as given).
  void set_damping_scale(double scale);

  /// Adds the linearised drag `drag` (outliving the shots that use it) to the damping of the
  /// following shots; null removes it. Each piece takes the segment of its midpoint.
  void set_drag(const DragProfile* drag);

  /// Shoots at `lambda` [1/s] with the tolerances scaled by `tolerance_factor`, recording the
  /// stations `stations_x` (x = s/L, in the order of integration) when given. `from_b` starts at
  /// s = L (Phi^ = 0, F^ = I there) and integrates toward s = 0; F is returned with its physical
  /// sign. Throws ShootingFailure.
  DampedShot shoot(std::complex<double> lambda,
                   double tolerance_factor = 1.0,
                   const std::vector<double>* stations_x = nullptr,
                   bool from_b = false);

  long total_shots() const;
  long total_steps() const;
  long total_rhs_evaluations() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The physical solution [Phi^; F^] at station j of a damped shot for the combination `c` of the
/// final basis, mapped back through the segment R factors.
Eigen::VectorXcd combine_damped_at_station(const DampedShot& shot,
                                           std::size_t j,
                                           const Eigen::VectorXcd& c);

}  // namespace catena::internal
