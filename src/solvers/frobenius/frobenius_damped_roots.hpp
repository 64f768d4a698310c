// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The complex roots of the damped boundary determinant (docs/explanation/methods/frobenius.md,
/// "Damping"). Each undamped root lambda = i Omega_n (frobenius_root_scan.hpp) is continued along
/// the drag scale s (eta -> s eta, s = 0 .. 1) by Muller's method on the determinant, which is
/// analytic in lambda; a root that reaches the real axis becomes a pair of overdamped roots, which
/// a scan of the real axis finds. The roots are then counted by the argument principle around a
/// rectangle of the lambda-plane (independently of how they were found).

#include <string>
#include <vector>

#include "solvers/frobenius/frobenius_damped_boundary.hpp"
#include "solvers/frobenius/frobenius_root_scan.hpp"

namespace catena::internal {

/// One damped root with its error estimates (relative, each part on its own).
struct DampedRoot {
  DampedComplex lambda;
  /// |error of Im lambda| / Im lambda (-1 for a real root).
  double omega_error = -1.0;
  /// |error of Re lambda| / |Re lambda|.
  double delta_error = -1.0;
};

/// The damped roots of one plane and how they were found.
struct DampedRoots {
  /// Complex roots, Im lambda > 0, ascending in Im lambda.
  std::vector<DampedRoot> modes;
  /// Real (overdamped) roots, ascending in -lambda.
  std::vector<DampedRoot> overdamped;
  /// Roots inside the counting rectangle by the argument principle (each complex pair counted
  /// twice), -1 when the count failed; and the number the found roots account for.
  int counted = -1;
  int expected = 0;
  double count_top = 0.0;
  std::vector<std::string> notes;
  std::vector<std::string> warnings;
  long evaluations = 0;
  double cancellation = 1.0;
  long terms = 0;
  int centres = 0;
  bool truncated = false;
  /// False when a root could not be continued or refined.
  bool complete = true;
};

/// The `count` lowest damped modes of `setup` (ordered by Im lambda) and the overdamped roots
/// below them.
DampedRoots find_damped_roots(const DampedSetup& setup, int count, const RootSettings& settings);

}  // namespace catena::internal
