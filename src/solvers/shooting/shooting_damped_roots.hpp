// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The characteristic roots of a damped line as the `shooting` solver finds them
/// (docs/explanation/methods/shooting.md, "Damping"): zeros of the analytic boundary determinant
/// D(lambda) of the damped shot (shooting_damped_integrator.hpp).
///
/// - muller_root: Muller's method (quadratic interpolation through the last three iterates), which
///   needs no derivative of D and converges to complex roots from a real or complex start.
///   Written here because neither Eigen nor SUNDIALS offers a complex scalar root finder.
/// - continue_root: the homotopy lambda(t), t the damping scale from 0 (the undamped line, whose
///   root i w0 the undamped path found) to 1, each step predicted by linear extrapolation and
///   corrected by Muller, the step halved (by 4) when Muller fails or lands farther from the
///   prediction than a fraction of the distance to the neighbouring undamped roots, doubled after
///   an easy step. A root the continuation cannot follow is reported with the reason.
/// - count_roots: the argument principle on the upper half of the rectangle
///   -delta_max <= Re lambda <= sigma, |Im lambda| <= top. D is real on the real axis (real
///   coefficients), so the change of arg D along the three edges in the upper half-plane, from
///   (sigma, 0) to (-delta_max, 0), is pi times the number N of roots in the whole (symmetric)
///   rectangle: N = 2 (complex roots with 0 < Im <= top) + (real roots in it). Each step of the
///   path is bisected until arg D changes by less than pi/4 along it.
/// - real_roots: sign changes of D on the negative real axis, refined by Brent's method.

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace catena::internal {

/// D(lambda) = determinant * exp(log_scale) (shooting_damped_integrator.hpp).
struct DampedValue {
  std::complex<double> determinant = 0.0;
  double log_scale = 0.0;
};

/// D at lambda [1/s] with the integration tolerances scaled by the factor.
using DampedFunction = std::function<DampedValue(std::complex<double> lambda, double factor)>;

struct MullerResult {
  bool converged = false;
  std::complex<double> root = 0.0;
  int iterations = 0;
  /// dD/dlambda at the root from the last interpolating parabola, as slope * exp(slope_log_scale).
  std::complex<double> slope = 0.0;
  double slope_log_scale = 0.0;
};

/// Muller's method from `guess`, with the first two points at guess + spread and guess + i spread;
/// converged when a step is at most `tolerance` |root|; fails after `max_iterations` steps or when
/// an iterate leaves the disc of `radius` around the guess.
MullerResult muller_root(const DampedFunction& f,
                         std::complex<double> guess,
                         double spread,
                         double tolerance,
                         double factor,
                         double radius,
                         int max_iterations = 40);

/// Secant steps at the tolerance factor `factor` from `start` (a root found at looser tolerances)
/// with the first step -D/slope (`slope` * exp(`slope_log_scale`) = dD/dlambda there): each step
/// uses the last two values; converged when a step is at most `tolerance` |root|. The result's
/// slope is the last secant's.
MullerResult secant_polish(const DampedFunction& f,
                           std::complex<double> start,
                           std::complex<double> slope,
                           double slope_log_scale,
                           double tolerance,
                           double factor,
                           int max_iterations = 8);

/// Settings of the homotopy.
struct ContinuationSettings {
  double tolerance = 1e-10;        ///< relative, for the root at t = 1
  double loose_tolerance = 1e-6;   ///< relative, for the roots at t < 1
  double radius_fraction = 0.3;    ///< largest move of a step / the gap to the neighbours
  double min_step = 1.0 / 4096.0;  ///< smallest step in t before the root is declared lost
  /// Tolerance factor of the shots of the steps and of the first Muller iterations at t = 1 (the
  /// root is then polished by secant steps at the factor 1).
  double loose_factor = 1.0;
  /// Polish the root at t = 1 (false: it stays at loose_tolerance; ContinuedRoot::polished).
  bool polish = true;
};

struct ContinuedRoot {
  bool ok = false;
  std::complex<double> root = 0.0;
  std::complex<double> slope = 0.0;  ///< MullerResult's, at t = 1
  double slope_log_scale = 0.0;
  bool polished = false;  ///< refined to `tolerance` at the factor 1
  /// The root reached the real axis before t = 1 (or was lost close to it, where two roots
  /// collide): the caller finds the real roots on the real axis, and the count checks them.
  bool went_real = false;
  int steps = 0;
  std::string reason;  ///< why the root was lost
};

/// Follows the root from `start` (t = 0) to t = 1 (or until it becomes real: went_real);
/// `set_scale(t)` sets the damping scale that `f` evaluates at; `gap` [1/s] is the distance from
/// `start` to the nearest other root at t = 0.
ContinuedRoot continue_root(const DampedFunction& f,
                            const std::function<void(double)>& set_scale,
                            std::complex<double> start,
                            double gap,
                            const ContinuationSettings& settings);

/// The argument-principle count (header) of the rectangle -delta_max <= Re <= sigma,
/// |Im| <= top [1/s], D evaluated with the tolerance factor `factor`.
struct RootCount {
  bool ok = false;
  int roots = 0;  ///< N in the whole rectangle (complex pairs count twice)
  long evaluations = 0;
  std::string reason;  ///< why the count failed
};
RootCount count_roots(
    const DampedFunction& f, double sigma, double delta_max, double top, double factor);

/// The real roots of D in [-delta_max, 0) from `samples` equal intervals, each sign change refined
/// by Brent's method to `tolerance` (relative), ascending in -lambda (the decay rate).
std::vector<double> real_roots(
    const DampedFunction& f, double delta_max, int samples, double tolerance, double factor);

}  // namespace catena::internal
