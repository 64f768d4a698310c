// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Where the next natural frequency of a plane is expected, from those found so far
/// (docs/explanation/methods/shooting.md, "Cost per root"). The root finder places its first
/// counting samples for mode n around this prediction, so that Brent starts in a bracket a few
/// prediction errors wide instead of one that reaches back to mode n - 1 (whose root makes the end
/// determinant vanish there too). A prediction is a place to look, never a result: the count
/// bracket and Brent decide, and a wrong prediction costs shots, not modes.
///
/// The frequencies of a cable are asymptotically equally spaced, out of plane smoothly, in plane
/// alternately (symmetric and antisymmetric modes have slightly different spacings, and an axial
/// mode now and then interrupts the pattern). Three extrapolations cover this: linear
/// (2 w_{n-1} - w_{n-2}), period-two (w_{n-1} + w_{n-2} - w_{n-3}) and quadratic; each is scored on
/// the modes it would have predicted, and the best scored one is used, its uncertainty the larger
/// of its last two errors times a safety factor.

#include <optional>
#include <vector>

namespace catena::internal {

/// A predicted frequency and the half-width of the interval it is expected in [rad/s].
struct RootPrediction {
  double omega = 0.0;
  double half_width = 0.0;
};

/// Predicts the next root of an ascending sequence of roots.
class RootPredictor {
 public:
  /// Uncertainty = kSafety x the chosen extrapolation's recent error.
  static constexpr double kSafety = 2.0;

  /// `min_half_width`: the smallest half-width returned, relative to the prediction [-].
  explicit RootPredictor(double min_half_width) : min_half_width_(min_half_width) {}

  /// Records the next root found (ascending; a multiple root once per mode).
  void add(double omega);

  /// The next root, or nothing while too few roots are known or when no extrapolation has
  /// predicted the last two roots to within a quarter of their spacing.
  std::optional<RootPrediction> next() const;

 private:
  static constexpr int kMethods = 3;
  // Extrapolation `method` from the roots before index `end` (needs end >= 3).
  double extrapolate(int method, std::size_t end) const;

  double min_half_width_;
  std::vector<double> roots_;
};

}  // namespace catena::internal
