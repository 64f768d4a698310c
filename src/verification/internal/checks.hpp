// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The checks of a solved scene (docs/reference/verdicts.md).

#include <vector>

#include "catena/solvers/solver_registry.hpp"
#include "catena/verification/findings.hpp"
#include "catena/verification/scene_runner.hpp"
#include "catena/verification/tolerance_table.hpp"

namespace catena::internal {

/// All checks for `result` (statics closure, solver status, cross-solver and published
/// comparisons as they are available).
/// Tolerances come from `tolerances` (first matching rule) unless the scene overrides them;
/// `findings` turns a reviewed disagreement with a published value into a source discrepancy;
/// `solvers` declare the computations each solver owns (a pair sharing one is not compared).
std::vector<CheckResult> run_checks(const SceneResult& result,
                                    const ToleranceTable& tolerances,
                                    const FindingsTable& findings,
                                    const std::vector<SolverEntry>& solvers = solver_registry());

}  // namespace catena::internal
