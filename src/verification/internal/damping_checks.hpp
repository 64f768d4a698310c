// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The checks of a damped scene (docs/reference/verdicts.md, "Damped scenes"): the decay rate
/// delta = -Re lambda of each mode compared between two solvers as the relative error of delta on
/// its own, the overdamped (real) roots both list, and a SKIP where a solver declined the damped
/// forced response the other computed. The damped frequency omega_d itself is the `frequency`
/// check (checks.cpp). None of these runs on an undamped scene, whose checks stay as they were.

#include "verification/internal/check_builder.hpp"

namespace catena::internal {

/// `decay-rate` checks of the modes a and b both return in `plane`, and `overdamped` checks of
/// the real roots both list there.
void damping_pair(const SolverOutput& a, const SolverOutput& b, Plane plane, CheckBuilder& builder);

/// A SKIP naming the reason when exactly one of a and b returned the damped forced response the
/// scene asked for (the other declined it: its summary's message says why).
void declined_forced_pair(const SolverOutput& a, const SolverOutput& b, CheckBuilder& builder);

}  // namespace catena::internal
