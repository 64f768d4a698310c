// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Damped forced response of the `shooting` solver (docs/explanation/methods/shooting.md,
/// "Damping"): one end driven as A cos(w t), the other fixed, solved as the complex boundary-value
/// problem at lambda = i w. The damped principal solutions (shooting_damped_integrator.hpp) are
/// shot from the fixed end and combined to meet the drive at the driven end (one complex D x D
/// solve). The response is Re[(x + i x_imag) e^{i w t}]: finite at a resonance. Its relative error
/// estimate is the change of the response (complex moduli, displacements and tension separately)
/// when it is computed again at 100x tighter tolerances, never below rtol.

#include "catena/solvers/solve_request.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/common/work_meter.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_integrator.hpp"

namespace catena::internal {

class DampedShootingIntegrator;

/// The plane the damped response to `forced` integrates (the string's for a straight
/// inextensible cable driven in plane).
Plane damped_forced_plane(const ShootingCoefficients& k, const ForcedRequest& forced);

/// The damped response at every frequency of `forced` with `integrator` (made for
/// damped_forced_plane, reused across calls: the fixed point of the drag linearisation calls this
/// once per iterate). `estimate` false skips the re-solve at tighter tolerances (the responses'
/// relative_error_estimate is then -1). Never throws ShootingFailure.
ForcedOutcome shooting_damped_forced_responses(DampedShootingIntegrator& integrator,
                                               const ShootingCoefficients& k,
                                               const ForcedRequest& forced,
                                               const Vector& stations,
                                               const IntegratorSettings& settings,
                                               bool estimate,
                                               WorkMeter* meter = nullptr);

/// The damped response at every frequency of `forced`, with the summary of that part (as
/// shooting_forced_responses). Never throws ShootingFailure.
ForcedOutcome shooting_damped_forced_responses(const ShootingCoefficients& k,
                                               const ForcedRequest& forced,
                                               const Vector& stations,
                                               const IntegratorSettings& settings,
                                               WorkMeter* meter = nullptr);

}  // namespace catena::internal
