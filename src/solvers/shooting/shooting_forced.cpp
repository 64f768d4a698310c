// SPDX-License-Identifier: MIT
// Forced response by superposition of principal solutions: see shooting_forced.hpp.
#include "solvers/shooting/shooting_forced.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "solvers/shooting/shooting_profile.hpp"

namespace catena::internal {

namespace {

// The largest relative error estimate of a response shooting returns; beyond it the forcing is
// at a natural frequency within the integration's accuracy.
constexpr double kResonanceEstimate = 0.1;

// The tolerance factor of the shot that measures a response's error estimate, and the largest
// ratio of its error to the error at the solver's tolerances assumed (the errors scale about
// linearly with the tolerance: 0.01 expected, 0.1 allowed).
constexpr double kEstimateFactor = 0.01;
constexpr double kTightErrorRatio = 0.1;

Vec2 drive_direction(const ShootingCoefficients& k, const ForcedRequest& forced, double s_driven) {
  switch (forced.direction) {
    case ForcingDirection::Tangential:
      return k.tangent(s_driven);
    case ForcingDirection::Normal:
      return k.normal(s_driven);
    default:
      return forced.unit_vector();
  }
}

}  // namespace

Drive make_drive(const ShootingCoefficients& k, const ForcedRequest& forced) {
  Drive drive;
  const double s_driven = forced.end == CableEnd::B ? k.length_m : 0.0;
  if (forced.direction == ForcingDirection::OutOfPlane) {
    drive.plane = Plane::OutOfPlane;
    drive.d = Eigen::VectorXd::Constant(1, forced.amplitude_m);
    return drive;
  }
  const Vec2 direction = drive_direction(k, forced, s_driven);
  drive.d = forced.amplitude_m * direction;
  if (!is_straight_inextensible(k)) return drive;
  // Only the normal part can move a straight inextensible cable (its axis is rigid).
  const double axial = direction.dot(k.tangent(s_driven));
  if (std::abs(axial) > 1e-12) {
    drive.diagnostic = fmt::format(
        "a straight inextensible cable cannot be displaced along its axis (axial part {:.3g} of "
        "the drive): no finite response",
        axial);
    return drive;
  }
  drive.string_only = true;
  drive.plane = Plane::OutOfPlane;
  drive.d = Eigen::VectorXd::Constant(1, forced.amplitude_m * direction.dot(k.normal(s_driven)));
  return drive;
}

namespace {

void set_profiles(ForcedResponse& response,
                  const Profile& p,
                  const Vector& stations,
                  bool inplane) {
  response.s_m = stations;
  if (inplane) {
    response.u = p.u;
    response.w = p.w;
    response.tension_n = p.tension;
  } else {
    response.v = p.v;
    response.tension_n = Vector::Zero(stations.size());
  }
  response.max_abs_tension_n = response.tension_n.cwiseAbs().maxCoeff();
}

// The response of one shot: the combination of its end basis that meets the drive.
Profile response_profile(const Shot& shot,
                         const Drive& drive,
                         const ShootingCoefficients& k,
                         const Vector& stations,
                         bool from_b) {
  const int D = drive.plane == Plane::InPlane ? 2 : 1;
  const Eigen::MatrixXd phi_end = shot.y_end.topRows(D);
  const Eigen::VectorXd c = phi_end.partialPivLu().solve(drive.d / k.length_m);
  Profile p = evaluate_profile(shot, c, k, stations, from_b, drive.plane);
  return drive.string_only ? string_as_inplane(p) : p;
}

// The largest change between two profiles of the same response, relative to each quantity's
// largest magnitude (displacements and tension separately).
double relative_change(const Profile& a, const Profile& b) {
  double change = 0.0;
  for (const auto& [x, y] : {std::pair{&a.u, &b.u}, std::pair{&a.w, &b.w}, std::pair{&a.v, &b.v},
                             std::pair{&a.tension, &b.tension}}) {
    if (x->size() == 0 || x->size() != y->size()) continue;
    const double scale = y->cwiseAbs().maxCoeff();
    if (scale > 0.0) change = std::max(change, (*x - *y).cwiseAbs().maxCoeff() / scale);
  }
  return change;
}

}  // namespace

ForcedResponse shooting_forced_response(ShootingIntegrator& integrator,
                                        const ShootingCoefficients& k,
                                        const ForcedRequest& forced,
                                        double omega,
                                        const Vector& stations,
                                        double relative_tolerance,
                                        bool& near_resonance) {
  ForcedResponse response;
  response.omega_rad_s = omega;
  const Drive drive = make_drive(k, forced);
  if (drive.diagnostic) {
    response.diagnostic = *drive.diagnostic;
    return response;
  }
  const bool from_b = forced.end == CableEnd::A;  // start at the fixed end
  const std::vector<double> x = scaled_stations(stations, k.length_m, from_b);
  const Shot shot = integrator.shoot(omega, 1.0, &x, from_b);
  // Resonance, relative to the integration's own accuracy: the response's error, about
  // rtol / |normalised det| (the combination below amplifies the basis's error by the condition
  // of Phi(L)), would reach kResonanceEstimate.
  const double resonance_level = relative_tolerance / kResonanceEstimate;
  if (std::abs(shot.determinant) <= resonance_level) {
    response.diagnostic = fmt::format(
        "forcing at a natural frequency (resonance): |det Phi(L)| / sqrt(det G) = {:.2e} <= "
        "{:.1e} (the integration tolerance {:.0e} / {:g}), no finite response",
        std::abs(shot.determinant), resonance_level, relative_tolerance, kResonanceEstimate);
    response.at_resonance = true;
    return response;
  }
  near_resonance = std::abs(shot.determinant) < 1e-3;
  response.near_resonance = near_resonance;
  const Profile p = response_profile(shot, drive, k, stations, from_b);
  set_profiles(response, p, stations, drive.plane == Plane::InPlane || drive.string_only);
  // The error estimate is measured: the change D of the response when the shot is repeated at
  // kEstimateFactor times the tolerances (it includes the amplification by the condition of
  // Phi(L), ~1 / |normalised det|, near a resonance). With the tight shot's error at most
  // kTightErrorRatio of this one's, the error e of this one satisfies |e| <= |D| / (1 - ratio).
  // Never below the relative tolerance asked.
  const Shot tight = integrator.shoot(omega, kEstimateFactor, &x, from_b);
  const Profile q = response_profile(tight, drive, k, stations, from_b);
  const double measured = relative_change(p, q) / (1.0 - kTightErrorRatio);
  response.relative_error_estimate = std::max(measured, relative_tolerance);
  return response;
}

ForcedOutcome shooting_forced_responses(const ShootingCoefficients& k,
                                        const ForcedRequest& forced,
                                        const Vector& stations,
                                        const IntegratorSettings& settings,
                                        WorkMeter* meter) {
  ForcedOutcome outcome;
  SolverSummary& summary = outcome.summary;
  const std::size_t asked = forced.omegas_rad_s.size();
  try {
    const Plane plane =
        forced.direction == ForcingDirection::OutOfPlane || is_straight_inextensible(k)
            ? Plane::OutOfPlane
            : Plane::InPlane;
    ShootingIntegrator integrator(plane, k, settings);
    for (double omega : forced.omegas_rad_s) {
      bool near_resonance = false;
      outcome.responses.push_back(shooting_forced_response(
          integrator, k, forced, omega, stations, settings.relative_tolerance, near_resonance));
      if (!outcome.responses.back().diagnostic.empty()) {
        summary.warnings.push_back(fmt::format("forced response at {:.10g} rad/s: {}", omega,
                                               outcome.responses.back().diagnostic));
      } else if (near_resonance) {
        summary.warnings.push_back(fmt::format(
            "forced response at {:.10g} rad/s is near a natural frequency (|det Phi(L)| / "
            "sqrt(det G) < 1e-3): the response is resonance-amplified and sensitive to omega",
            omega));
      }
      if (meter && meter->stop_after(static_cast<long>(outcome.responses.size()))) break;
    }
    summary.termination = Termination::Converged;
    summary.message = fmt::format("{} of {} forced frequencies", outcome.responses.size(), asked);
    summary.iterations = static_cast<long>(asked);
    summary.operations = integrator.total_rhs_evaluations();
  } catch (const ShootingFailure& failure) {
    summary.termination =
        outcome.responses.empty() ? Termination::NumericalFailure : Termination::NoConvergence;
    summary.message = fmt::format("{} of {} forced frequencies ({})", outcome.responses.size(),
                                  asked, failure.what());
    summary.warnings.push_back(fmt::format("forced response: {}", failure.what()));
  }
  return outcome;
}

}  // namespace catena::internal
