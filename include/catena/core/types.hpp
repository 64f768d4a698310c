// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Small shared vocabulary: vector aliases and constants.

#include <Eigen/Core>
#include <limits>

namespace catena {

using Index = Eigen::Index;
using Vector = Eigen::VectorXd;
using Vec2 = Eigen::Vector2d;

/// Infinity, used for `EA = inf` (inextensible cable).
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr double kPi = 3.141592653589793238462643383279502884;

/// In-plane (the vertical plane of the supports) or out-of-plane motion: they decouple.
enum class Plane { InPlane, OutOfPlane };

/// "in-plane" or "out-of-plane", for messages and reports.
inline const char* to_string(Plane plane) {
  return plane == Plane::InPlane ? "in-plane" : "out-of-plane";
}

}  // namespace catena
