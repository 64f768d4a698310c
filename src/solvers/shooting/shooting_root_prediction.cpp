// SPDX-License-Identifier: MIT
// The next root of a plane from the roots found so far: see shooting_root_prediction.hpp.
#include "solvers/shooting/shooting_root_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace catena::internal {

void RootPredictor::add(double omega) { roots_.push_back(omega); }

double RootPredictor::extrapolate(int method, std::size_t end) const {
  const double r1 = roots_[end - 1], r2 = roots_[end - 2], r3 = roots_[end - 3];
  switch (method) {
    case 0:
      return 2.0 * r1 - r2;  // equal spacing
    case 1:
      return r1 + (r2 - r3);  // alternating spacing (in plane)
    default:
      return 3.0 * r1 - 3.0 * r2 + r3;  // slowly changing spacing
  }
}

std::optional<RootPrediction> RootPredictor::next() const {
  const std::size_t size = roots_.size();
  if (size < 4) return std::nullopt;
  // Each extrapolation scored by its larger error on the last two roots it could have predicted.
  int best = 0;
  double best_error = std::numeric_limits<double>::infinity();
  for (int method = 0; method < kMethods; ++method) {
    double error = 0.0;
    for (std::size_t end = std::max<std::size_t>(3, size - 2); end < size; ++end) {
      error = std::max(error, std::abs(extrapolate(method, end) - roots_[end]));
    }
    if (error < best_error) {
      best_error = error;
      best = method;
    }
  }
  RootPrediction prediction;
  prediction.omega = extrapolate(best, size);
  prediction.half_width =
      std::max(kSafety * best_error, min_half_width_ * std::abs(prediction.omega));
  const double spacing = roots_[size - 1] - roots_[size - 2];
  if (!(prediction.half_width < 0.25 * spacing) || !(prediction.omega > roots_.back()))
    return std::nullopt;
  return prediction;
}

}  // namespace catena::internal
