// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The shared driver of the dynamic tension in waves (docs/explanation/dynamic-tension.md): for
/// each excitation of the motion request (each period of a regular motion, or the irregular
/// motion) it iterates the drag linearisation to its fixed point. An iterate is the velocity
/// scale V(s) of the response at the request's stations (normal and tangential); the map is
///
///     V -> DragProfile(V) -> the solver's damped forced response (forced_with_drag, the
///          solver's own numerics) -> the velocity scales of that response,
///
/// iterated by KINSOL's Anderson-accelerated fixed point (anderson_fixed_point.hpp). The driver
/// shares no linear solve between solvers: each solver's fixed point is its own witness. After
/// the iteration the response at the final iterate is computed once more; its velocity scales
/// give the reported residual (the fixed point's own consistency) and its tension the results.
/// A fixed point that does not reach the tolerance is reported with its residual, as
/// NoConvergence.

#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "solvers/common/solver_driver.hpp"

namespace catena::internal {

/// The dynamic tension of every excitation of context.request.motion, with the summary of that
/// part ("dynamic tension": termination, message, iterations, max residual and error estimate).
/// A solver that does not handle drag (SolverNumerics::handles_drag) gets a NotApplicable part.
SolverSummary solve_dynamic_tension(const SolveContext& context,
                                    SolverNumerics& numerics,
                                    std::vector<DynamicTension>& results);

}  // namespace catena::internal
