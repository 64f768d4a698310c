// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Bisection of a sign change down to adjacent doubles, shared by the seabed statics' root finds
/// (written by hand: each predicate is a monotone step of a closed-form construction, and the
/// answer must be the last double on one side, which no library bracketing routine promises).

#include <algorithm>
#include <cmath>

namespace catena::internal {

/// Bisection of [lo, hi] (either order) down to adjacent doubles, or 1e-17 of the bracket so that
/// a root at 0 does not walk through the subnormals: `below(x)` says whether x is on the side of
/// lo. Returns the last x on the side of lo.
template <class Below>
double bisect(double lo, double hi, Below below) {
  const double floor = 1e-17 * std::abs(hi - lo);
  for (int i = 0; i < 200 && std::abs(hi - lo) > floor; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= std::min(lo, hi) || mid >= std::max(lo, hi)) break;
    (below(mid) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace catena::internal
