// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Finds the natural frequencies behind a scene's forced-response condition number
/// (catena/verification/forced_conditioning.hpp): from the most accurate exact solver that ran
/// (smallest declared accuracy among the `family = "exact"` solvers of the tolerance table whose
/// run converged) whose output already holds the forced plane's modes up to above the highest
/// forcing frequency; otherwise solved for, by fe first (whether or not the scene ran it: the
/// condition number needs the frequencies to ~1e-4 only, and fe is the cheapest by far), then by
/// the exact solvers that ran (the scene's request without the forcing, the forced plane's modes
/// only, doubling their number from 8 up to 64 until the top one lies 5% above the highest forcing
/// frequency, within 10 s per scene; solves the doubling would discard are skipped where the
/// modes' growth predicts them too low, the list kept is the same).

#include <cstddef>
#include <vector>

#include "catena/verification/forced_conditioning.hpp"
#include "catena/verification/scene_runner.hpp"

namespace catena::internal {

/// The doubling's first and largest mode counts.
inline constexpr int kFirstConditioningModes = 8;
inline constexpr int kMostConditioningModes = 64;

/// The count the doubling from kFirstConditioningModes stops at for the lowest modes `omegas`
/// [rad/s]: the first whose top mode lies above `top`, the largest tried when none does (at most
/// omegas.size()).
std::size_t doubling_count(const std::vector<double>& omegas, double top);

/// The next count to solve for after `solved` modes whose top one, `highest` [rad/s], lies at or
/// below `top`: twice `solved`, or a larger power of two (up to kMostConditioningModes) when
/// omega_n ~ n puts `top` beyond it.
int next_count(int solved, double highest, double top);

ForcedConditioning find_forced_conditioning(const SceneResult& result,
                                            const ToleranceTable& tolerances,
                                            const RunLimits& limits);

}  // namespace catena::internal
