// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// How `fe` meets an accuracy target it was asked for (FeSolverOptions::tolerance): when a mode's
/// error estimate exceeds the target, the whole solve is repeated on a finer mesh, N predicted
/// from the estimates' order in N (4 with Richardson, 2 without), until every mode meets the
/// target, the mesh would exceed `max_elements`, or a refinement stops paying (the estimate is
/// then held up by a part that does not fall with N: rounding, the statics' floor, the penalty).
/// docs/explanation/methods/fe.md, "Meeting a tolerance".

#include <string>
#include <vector>

namespace catena::internal {

/// One refinement's inputs: the mesh just solved and the error estimates it gave (relative; a
/// negative value is a mode without an estimate, which a finer mesh cannot give one).
struct FeRefinementState {
  int elements = 0;
  int max_elements = 0;
  double tolerance = 0.0;
  bool richardson = true;
  std::vector<double> estimates;
  /// The largest estimate among the missed modes of the previous mesh (0: this is the first).
  double previous_worst = 0.0;
};

/// The largest estimate above the tolerance (0 when every mode with an estimate meets it).
double fe_worst_miss(const std::vector<double>& estimates, double tolerance);

/// The next mesh, or why there is none.
struct FeRefinementStep {
  int elements = 0;         // 0: no refinement
  std::string stop_reason;  // why not, when a mode still misses the target (empty otherwise)
};

/// The next mesh: N times (1.25 (worst / tolerance)^(1/order)), at least 2x and at most 8x,
/// a multiple of 4 (so that N/2 is even, for the estimate mesh), capped at max_elements. None when
/// every mode meets the target or no mode has an estimate to improve (no reason), when the cap is
/// reached, or when the last refinement did not halve the worst miss (with the reason).
FeRefinementStep fe_refined_elements(const FeRefinementState& state);

}  // namespace catena::internal
