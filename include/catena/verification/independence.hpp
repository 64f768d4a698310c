// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Two solvers that compute a quantity by the same code are one witness, not two
/// (docs/reference/verdicts.md, "Independence"). Each solver declares its code paths
/// (SolverEntry::computations); the harness does not compare two solvers on a quantity they share,
/// and flags, from the values themselves, any pair of solvers whose values of a quantity are
/// bit-identical over a whole list (an identity check: it cannot fail).

#include <optional>
#include <string>
#include <vector>

#include "catena/solvers/solver_registry.hpp"
#include "catena/verification/check_result.hpp"
#include "catena/verification/scene_runner.hpp"

namespace catena {

/// The detail of the SKIP recorded for a pair not compared because of a shared computation
/// starts with this text, followed by the id.
inline constexpr const char* kSharedComputationDetail = "not compared: shared computation ";
/// The check kind of an identity flag.
inline constexpr const char* kIdentityCheck = "identity";

/// The id both `a` and `b` declare for `quantity` ("frequency-in-plane", ...), or nullopt when
/// they differ or either declares none.
std::optional<std::string> shared_computation(const SolverEntry& a,
                                              const SolverEntry& b,
                                              const std::string& quantity);

/// An identity flag (kIdentityCheck, verdict FAIL) for every group of cross-solver value checks
/// ("frequency", "tension", "forced", "dynamic-tension"; same compare and plane; skipped checks and
/// pairs of exact zeros left out) with at least two values, all finite and bit-identical between
/// the two solvers.
std::vector<CheckResult> identity_checks(const std::vector<CheckResult>& checks);

/// What a run's summary reports about independence.
struct IndependenceTally {
  /// Identity flags: cross-solver checks whose two values come from shared code (target 0).
  int identity_checks = 0;
  /// Pairs x quantities not compared because the two solvers share the computation.
  int shared_not_compared = 0;
};
IndependenceTally tally_independence(const std::vector<SceneResult>& results);

}  // namespace catena
