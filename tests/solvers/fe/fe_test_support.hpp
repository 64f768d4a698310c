// SPDX-License-Identifier: MIT
#pragma once
// Problems several fe stage tests share.

#include "catena/models/cable.hpp"

namespace catena::testing {

/// A straight bar: L = 1 m, EA = 10 N, m = 1 kg/m, stretched to 1.1 m (T = 1 N), weight 1e-9 N/m
/// (so that the statics have a direction): axial frequencies n pi sqrt(EA/m) / L exactly.
inline Problem straight_bar() {
  Problem problem;
  problem.cable.length_m = 1.0;
  problem.cable.weight_n_per_m = 1e-9;
  problem.cable.axial_stiffness_n = 10.0;
  problem.cable.mass_kg_per_m = 1.0;
  problem.supports.b_m = Vec2(1.1, 0.0);
  return problem;
}

}  // namespace catena::testing
