// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The modes of one plane of a damped line by the `shooting` solver
/// (docs/explanation/methods/shooting.md, "Damping"):
///
///   1. the undamped roots w0 of the same line with the damping removed (count + 1 of them, by
///      the undamped root finder at a loose bracket: they are only starting points);
///   2. each continued from i w0 to its damped root lambda along the damping scale t in [0, 1]
///      (continue_root), refined to the solver's tolerance;
///   3. complex roots ordered by omega_d = Im lambda; roots that became real are found again on
///      the real axis (real_roots) and listed as overdamped;
///   4. the argument-principle count of the rectangle -delta_max <= Re lambda <= sigma,
///      0 < Im lambda <= omega_top (1 + margin) proves the number of roots returned, or the plane
///      says what it does not prove;
///   5. error estimates of omega_d and delta separately from the roots found again at 100x
///      tighter tolerances; complex shapes and tension from the null vector of Phi(L).

#include "catena/solvers/modal_result.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_integrator.hpp"
#include "solvers/shooting/shooting_root_finder.hpp"

namespace catena::internal {

/// What the damped plane needs of the solver's options.
struct DampedPlaneSettings {
  IntegratorSettings integrator;
  /// The undamped root finder's settings (its bracket is loosened here: the roots only start
  /// the continuation).
  RootFinderSettings undamped;
  /// Relative tolerance of the final Muller steps [-].
  double root_tolerance = 1e-10;
  /// One extra refinement per root at 100x tighter tolerances.
  bool error_estimate = true;
  /// The smallest relative error estimate reported (the solver's accuracy target).
  double estimate_floor = 0.0;
  /// String estimate of a frequency above the wanted modes [rad/s] (the undamped finder's start).
  double first_guess_rad_s = 1.0;
};

/// The `count` lowest damped modes of `plane` (by omega_d) with the overdamped roots found, and
/// the plane's summary (termination, message naming the counted region, notes). Throws
/// ShootingFailure when a shot fails.
ModalResult damped_plane_modes(const ShootingCoefficients& k,
                               const SolveContext& context,
                               Plane plane,
                               int count,
                               const DampedPlaneSettings& settings);

}  // namespace catena::internal
