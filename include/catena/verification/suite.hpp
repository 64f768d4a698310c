// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Running many scenes on all cores (the engine of `catena verify` and `catena report`).

#include <functional>
#include <string>
#include <vector>

#include "catena/verification/scene_runner.hpp"

namespace catena {

/// Called after each scene: (scenes done, total, name of the scene just finished). Calls are
/// serialised (never concurrent).
using SuiteProgress = std::function<void(std::size_t, std::size_t, const std::string&)>;

/// Runs `scenes` on `jobs` threads (0: all cores); results in the order of `scenes`. Throws
/// InvalidInput (before any work) when `options` is invalid (SceneRunOptions::validate).
std::vector<SceneResult> run_scenes(const std::vector<Scene>& scenes,
                                    int jobs,
                                    const SceneRunOptions& options = {},
                                    const SuiteProgress& progress = {});

}  // namespace catena
