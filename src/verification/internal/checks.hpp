#pragma once
/// \file
/// The checks of a solved scene (DESIGN.md §3).

#include <vector>

#include "catena/verification/scene_runner.hpp"

namespace catena::internal {

/// All checks for `result` (statics closure, solver status, cross-solver and published
/// comparisons as they are available).
std::vector<CheckResult> run_checks(const SceneResult& result);

}  // namespace catena::internal
