// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `fe` solver's summary text: resolution, the notes and message of each plane (mode count
/// proof, eigenpair quality, observed order, discrete statics, stage times), the forced part's
/// message, and the reasons for declining. Numbers are computed elsewhere; this file only words
/// them.

#include <string>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "solvers/common/solver_driver.hpp"
#include "solvers/fe/fe_levels.hpp"

namespace catena::internal {

/// "12.3 us" below a millisecond, "4.567 ms" above.
std::string format_seconds(double seconds);

/// "N = 400, 800 elements, Richardson (order 2 -> 4)" (+ the penalties when inextensible).
std::string fe_resolution(const FePlan& plan);

/// The whole-run facts: resolution, and the penalty warning of an inextensible cable.
void describe_fe_run(const FePlan& plan, SolverSummary& summary);

/// Why the in-plane chain is declined: too stiff for double precision (rounding floor of mode 1
/// above `max_floor`).
std::string fe_rounding_floor_decline(const FePlan& plan, double t0_n, double max_floor);

/// What the summary of one plane says about how its modes were obtained.
struct FePlaneFacts {
  Plane plane = Plane::InPlane;
  int modes_asked = 0;
  int modes_available = 0;
  /// The elements of the N/2 estimate mesh that could not be used (no coarse mesh), for the
  /// warning.
  int estimate_elements = 0;
  bool has_coarse = false;
  /// The eigen solve on the reference level (finest main mesh, first penalty) and its mesh.
  const FeEigenSolution* finest = nullptr;
  const FeChain* finest_chain = nullptr;
  bool prescribed_forces = false;
  bool inertia_proved_everywhere = false;
  const FePlaneEigenReport* eigen = nullptr;
  /// Observed orders per mode (empty: not asked), from the last three meshes of the plan.
  std::vector<double> observed_orders;
  const FePlan* plan = nullptr;
  const FeTimings* timings = nullptr;
};

/// Adds the notes and warnings of `facts` to `result.summary` and sets its message (the
/// termination must be final).
void describe_fe_plane(const FePlaneFacts& facts, ModalResult& result);

/// The note naming the modes whose unextrapolated frequencies on N/2, N, 2N converge below
/// Richardson's assumed order 2 (`low_orders`: each one's extrapolated omega and observed order, 0
/// where the differences change sign), whose estimates therefore come from the observed order
/// (fe_extrapolation.hpp, mesh_estimate).
std::string low_order_note(const FePlan& plan,
                           const std::vector<Mode>& modes,
                           const std::vector<std::pair<double, double>>& low_orders);

/// The notes on the discrete statics of `chain` and on the stage times so far (the damped planes
/// add them as describe_fe_plane does).
std::string fe_statics_note(const FeChain& chain, bool prescribed_forces);
std::string fe_time_note(const FeTimings& timings);

/// The message of a plane whose eigen solve failed numerically on some level.
std::string fe_eigen_failure_message(Plane plane, const FePlaneEigenReport& eigen);

/// The forced part's message ("Converged: k of n forced frequencies ...") and time note.
void describe_forced(ForcedOutcome& outcome, const FeTimings& timings);

}  // namespace catena::internal
