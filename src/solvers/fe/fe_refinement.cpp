// SPDX-License-Identifier: MIT
// Mesh refinement toward fe's accuracy target: fe_refinement.hpp.
#include "solvers/fe/fe_refinement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace catena::internal {
namespace {

// A refinement must at least halve the worst miss to be worth another: below that, the estimate
// is held up by a part that does not fall with N (fe_refinement.hpp).
constexpr double kMinGain = 2.0;
// Margin on the predicted mesh: the (n/N)^order law is asymptotic, and a mesh that just misses
// costs a whole extra solve.
constexpr double kMargin = 1.25;
constexpr double kMinFactor = 2.0;
constexpr double kMaxFactor = 8.0;

int round_up_to_multiple_of_4(double elements) {
  return 4 * static_cast<int>(std::ceil(elements / 4.0));
}

}  // namespace

double fe_worst_miss(const std::vector<double>& estimates, double tolerance) {
  double worst = 0.0;
  for (double estimate : estimates)
    if (estimate > tolerance) worst = std::max(worst, estimate);
  return worst;
}

FeRefinementStep fe_refined_elements(const FeRefinementState& state) {
  if (!(state.tolerance > 0.0)) return {};
  const double worst = fe_worst_miss(state.estimates, state.tolerance);
  if (worst == 0.0) return {};
  if (state.previous_worst > 0.0 && worst > state.previous_worst / kMinGain)
    return {
        0,
        fmt::format(
            "the last refinement took the largest estimate from {:.1e} only to {:.1e} (a part that "
            "does not fall with N holds it up)",
            state.previous_worst, worst)};
  const double order = state.richardson ? 4.0 : 2.0;
  const double factor =
      std::clamp(kMargin * std::pow(worst / state.tolerance, 1.0 / order), kMinFactor, kMaxFactor);
  const int cap = 4 * (state.max_elements / 4);
  const int next = std::min(round_up_to_multiple_of_4(factor * state.elements), cap);
  if (next <= state.elements)
    return {0, fmt::format("max_elements = {} reached", state.max_elements)};
  return {next, ""};
}

}  // namespace catena::internal
