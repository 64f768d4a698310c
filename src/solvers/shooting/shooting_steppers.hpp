// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The integrators a `shooting` shot can be stepped by ("Integrators" in
/// docs/explanation/methods/shooting.md): one interface, ShotStepper, for the explicit Runge-Kutta
/// pair (shooting_runge_kutta.hpp; the default) and CVODE's Adams or BDF. Private to the shooting
/// solver.

#include <sundials/sundials_context.h>

#include <memory>

#include "solvers/shooting/shooting_integrator.hpp"
#include "solvers/shooting/shooting_system.hpp"

namespace catena::internal {

/// One integration method as a shot drives it: a state of fixed size,
/// advanced one accepted step at a time up to a stop point (a break or the end), and restarted in
/// place where the shot changes the state (a re-orthonormalisation, a point's jump, a new piece,
/// the end of the grounded run).
class ShotStepper {
 public:
  virtual ~ShotStepper() = default;
  /// The state (its size fixed at construction); the shot changes it only before restart().
  virtual double* state() = 0;
  /// A new shot from x = 0 with the state set: tolerances of Y (and S) and of the phase.
  virtual void begin(double rtol, double atol, double atol_phase, double stop) = 0;
  /// Goes on from x after the shot changed the state there.
  virtual void restart(double x, double stop) = 0;
  /// One accepted step toward `stop`; returns the x reached.
  virtual double step(double stop) = 0;
  /// The state at xs inside the last step.
  virtual void state_at(double xs, double* out) = 0;
  /// Steps and right-hand-side evaluations since begin.
  virtual long steps() const = 0;
  virtual long rhs_evaluations() const = 0;
};

/// The stepper of `settings.method` for the plain state (slope = false) or the state with the
/// frequency derivative, on the right-hand side of `data` (kept by reference: it must outlive the
/// stepper). `context` is used by CVODE only.
std::unique_ptr<ShotStepper> make_shot_stepper(const IntegratorSettings& settings,
                                               SUNContext context,
                                               int dimension,
                                               bool slope,
                                               RhsData& data);

}  // namespace catena::internal
