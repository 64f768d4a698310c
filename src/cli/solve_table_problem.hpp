// SPDX-License-Identifier: MIT
#pragma once
// What `catena solve` says about the problem before its tables: the statics in one or two lines
// (H, the tensions at both ends, the closure, the seabed contact), and under --verbose the
// problem's description (cable or line, damping, drag, dimensionless groups, the line's statics
// at every joint and point).

#include <string>

#include "catena/verification/scene_runner.hpp"

namespace catena::cli {

/// The statics lines (each ending in a newline, indented by two spaces).
std::string statics_text(const SceneResult& result);

/// The problem's description for --verbose (each line ending in a newline).
std::string problem_text(const SceneResult& result);

}  // namespace catena::cli
