// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Forced response of the `shooting` solver (docs/explanation/methods/shooting.md): one end of the
/// cable is driven harmonically, the other is fixed. The principal solutions are shot from the
/// fixed end and combined to meet the prescribed displacement at the driven end (one D x D solve
/// per frequency). The response's relative error estimate is rtol / |normalised det Phi(L)| (the
/// principal solutions' error amplified by the condition of the solve); a frequency where that
/// estimate would reach 0.1, i.e. |det| <= 10 rtol, is reported as resonance (no finite
/// response); one with |det| < 1e-3 is flagged near_resonance with a warning. A straight
/// inextensible cable responds only to the normal part of the drive.

#include <Eigen/Core>
#include <optional>
#include <string>

#include "catena/solvers/solve_request.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/common/work_meter.hpp"
#include "solvers/shooting/shooting_coefficients.hpp"
#include "solvers/shooting/shooting_integrator.hpp"

namespace catena::internal {

/// The prescribed end displacement in the integration variables: which plane is integrated, the
/// drive d [m] (a D-vector; a straight inextensible cable: its normal part, integrated as the
/// string), and why there is no response, if there is none. Shared with the damped response.
struct Drive {
  Plane plane = Plane::InPlane;
  Eigen::VectorXd d;
  bool string_only = false;
  std::optional<std::string> diagnostic;
};
Drive make_drive(const ShootingCoefficients& k, const ForcedRequest& forced);

/// The response at one frequency; `near_resonance` is set when |det Phi(L)| < 1e-3. A response
/// with a diagnostic (resonance, an axial drive of a rigid cable) has no profiles. Throws
/// ShootingFailure when the shot fails.
ForcedResponse shooting_forced_response(ShootingIntegrator& integrator,
                                        const ShootingCoefficients& k,
                                        const ForcedRequest& forced,
                                        double omega,
                                        const Vector& stations,
                                        double relative_tolerance,
                                        bool& near_resonance);

/// The response at every frequency of `forced`, with the summary of that part: Converged with
/// warnings for resonances, or, when the integration fails, the responses computed before the
/// failure (NoConvergence; NumericalFailure when there are none). Never throws ShootingFailure.
/// A `meter` is told each frequency done and may stop early (the responses computed so far).
ForcedOutcome shooting_forced_responses(const ShootingCoefficients& k,
                                        const ForcedRequest& forced,
                                        const Vector& stations,
                                        const IntegratorSettings& settings,
                                        WorkMeter* meter = nullptr);

}  // namespace catena::internal
