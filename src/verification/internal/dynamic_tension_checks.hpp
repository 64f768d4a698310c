// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The checks of a scene that asks the dynamic tension under a motion of end b
/// (`[request.motion]`; docs/reference/verdicts.md, "Dynamic tension"):
///
/// - `dynamic-tension`: each pair of solvers that computed the same excitation, at the fairlead,
///   at the anchor and along the line (max-norm over the stations), the tension amplitude
///   (regular) or standard deviation (irregular), and the motion along the line, held to the
///   table's rule;
/// - `fixed-point`: each solver's fixed point of the drag linearisation is converged within the
///   request's tolerance, and never claimed converged beyond it;
/// - `drag-consistency`: regular motion with drag, the linearised damping c(s) each solver reports
///   recomputed by the harness from its own final motion (a bound of sqrt(2) x its residual);
/// - `drag-anchor`: a scene without drag that also asks the forced response at the same frequency,
///   direction and end: the dynamic tension is the same solver's damped forced response |tau|.
///
/// The estimates of the dynamic tension are checked with the others (estimate_checks.hpp).

#include <vector>

#include "verification/internal/check_builder.hpp"

namespace catena::internal {

/// The plane labels of the dynamic-tension checks: where on the line the value is.
inline constexpr const char* kFairleadPlace = "fairlead";
inline constexpr const char* kAnchorPlace = "anchor";
inline constexpr const char* kStationsPlace = "stations";
/// The motion amplitude (or standard deviation) along the line, max-norm over the stations.
inline constexpr const char* kMotionPlace = "motion";
/// The plane label of a solver's own fixed-point, consistency and anchor checks.
inline constexpr const char* kDynamicPlace = "dynamic";

/// The tension value the checks compare at an end: the amplitude (regular) or the standard
/// deviation (irregular) [N].
double dynamic_end_value(const DynamicTension& t, const DynamicTensionEnd& end);
/// The tension along the line the checks compare: amplitude_n (regular) or std_n (irregular).
const Vector& dynamic_station_values(const DynamicTension& t);

/// Every dynamic-tension check of the scene: pair checks between the `usable` outputs, and each
/// output's own fixed-point, consistency and anchor checks (for every output that returned a
/// dynamic tension, usable or not: a claim of convergence is checked wherever it is made).
void dynamic_tension_checks(const std::vector<const SolverOutput*>& usable, CheckBuilder& builder);

}  // namespace catena::internal
