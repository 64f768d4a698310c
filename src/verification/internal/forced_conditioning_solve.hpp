#pragma once
/// \file
/// Finds the natural frequencies behind a scene's forced-response condition number
/// (catena/verification/forced_conditioning.hpp): from the most accurate exact solver that ran
/// (smallest declared accuracy among the `family = "exact"` solvers of the tolerance table whose
/// run converged), taken from its output when it already holds the forced plane's modes up to
/// above the highest forcing frequency, otherwise solved for them (the scene's request without the
/// forcing, the forced plane's modes only, doubling their number from 8 up to 64 until the top one
/// lies 5% above the highest forcing frequency, within 10 s per scene; solves the doubling would
/// discard are skipped where the modes' growth predicts them too low, the list kept is the same).

#include "catena/verification/forced_conditioning.hpp"
#include "catena/verification/scene_runner.hpp"

namespace catena::internal {

ForcedConditioning find_forced_conditioning(const SceneResult& result, const ToleranceTable& tolerances,
                                            const RunLimits& limits);

}  // namespace catena::internal
