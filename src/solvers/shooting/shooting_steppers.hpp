// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The integrators a `shooting` shot can be stepped by ("Integrators" in
/// docs/explanation/methods/shooting.md): one interface, ShotStepper, for SUNDIALS ARKODE's
/// ERKStep with Verner's 6(5) pair (the default) and SUNDIALS CVODE's Adams or BDF. Private to
/// the shooting solver.

#include <arkode/arkode_erkstep.h>
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

/// ARKODE's Verner 6(5) pair (ARKODE_VERNER_8_5_6) with a ninth, first-same-as-last stage: row 9
/// of A is b (the stage's value is the step's solution), c_9 = 1 and b_9 = d_9 = 0, so the method
/// and its error estimate are Verner's. Why: SUNDIALS 6.4.1's ERKStep (Debian's) takes f at the
/// end of a step from the last stage whenever the last node is 1, without checking that the last
/// stage is the solution (llnl/sundials issue #311, fixed in later releases). Verner's last node is
/// 1 and its last stage is not the solution, so with the plain table each step started from a
/// wrong derivative and the method fell to order 3 (observed on y'' = -100 y; 1,215 steps and an
/// error of 2.4e-9 at rtol 1e-10 over 1.6 periods). With the added stage the shortcut is right on
/// any version, and it costs no evaluation: 8 a step (7 stages after the first, plus the end
/// point), what the pair needs. The caller owns the table (ARKodeButcherTable_Free); null when
/// SUNDIALS cannot allocate it.
ARKodeButcherTable verner_table_with_fsal_stage();

/// The stepper of `settings.method` for the plain state (slope = false) or the state with the
/// frequency derivative, on the right-hand side of `data` (kept by reference: it must outlive the
/// stepper). `context` is the SUNDIALS context of the integrator.
std::unique_ptr<ShotStepper> make_shot_stepper(const IntegratorSettings& settings,
                                               SUNContext context,
                                               int dimension,
                                               bool slope,
                                               RhsData& data);

/// The stepper of `settings.method` for a damped shot: the complex basis Y (2D x D) as 4 D^2
/// reals, interleaved real and imaginary parts, on damped_rhs_values (shooting_system.hpp) at
/// data.lambda; error weights 1 / (rtol |z| + atol) per complex component; CVODE's Newton uses
/// difference-quotient Jacobians.
std::unique_ptr<ShotStepper> make_damped_stepper(const IntegratorSettings& settings,
                                                 SUNContext context,
                                                 int dimension,
                                                 RhsData& data);

}  // namespace catena::internal
