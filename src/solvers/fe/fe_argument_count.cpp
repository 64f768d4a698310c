// SPDX-License-Identifier: MIT
// The argument-principle count of the damped fe chain's roots: see fe_argument_count.hpp.
#include "solvers/fe/fe_argument_count.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "catena/core/types.hpp"

namespace catena::internal {
namespace {

using Complex = std::complex<double>;

// The change of phase from a to b, reduced to (-pi, pi].
double phase_change(double a, double b) {
  double d = std::remainder(b - a, 2.0 * kPi);
  if (d <= -kPi) d += 2.0 * kPi;
  return d;
}

// Largest change per step, and the change below which the step doubles.
constexpr double kMaxPhaseStep = kPi / 4.0;
constexpr double kGrowPhaseStep = kPi / 16.0;

struct Walker {
  const std::vector<Complex>& known;
  ComplexBandedLdlt& factor;
  long evaluations = 0;
  std::string failure;

  // Distance from z to the nearest known root (infinite without any).
  double clearance(Complex z) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (Complex root : known) nearest = std::min(nearest, std::abs(z - root));
    return nearest;
  }

  // The phase of det Q at z and its derivative d(log det Q)/dz; false when a pivot vanishes (a
  // root on the boundary to rounding).
  bool phase_at(Complex z, double& phase, Complex& derivative) {
    ++evaluations;
    if (!factor.factorize(z) || !(factor.pivot_ratio() > 1e-15)) {
      failure = fmt::format(
          "Q(lambda) is singular to rounding at lambda = {:.6e}{:+.6e}i on the boundary", z.real(),
          z.imag());
      return false;
    }
    phase = factor.determinant_phase();
    derivative = factor.log_derivative(z);
    return true;
  }

  // Adds the phase change from a to b to `winding` (phase_a, derivative_a at a on entry, at b on
  // return). Each step's change is measured modulo 2 pi and unwrapped to the branch nearest the
  // trapezoid rule on the phase's derivative Im(g dz); the step is accepted when that prediction
  // and the unwrapped change agree within pi/8 and the change is below pi/4.
  bool walk(Complex a, Complex b, double& phase_a, Complex& derivative_a, double& winding) {
    const double length = std::abs(b - a);
    const Complex direction = (b - a) / length;
    double t = 0.0, step = 1.0 / 16.0;
    while (t < 1.0) {
      // No step longer than the distance to the nearest known root: each root subtends at most
      // 2 atan(1/2) of phase.
      const double limit = clearance(a + t * (b - a)) / length;
      const double next = std::min({1.0, t + step, t + std::max(limit, 1e-15)});
      double phase = 0.0;
      Complex derivative;
      if (!phase_at(a + next * (b - a), phase, derivative)) return false;
      const double s = (next - t) * length;
      const double predicted =
          0.5 * s * (std::imag(derivative_a * direction) + std::imag(derivative * direction));
      const double measured = phase_change(phase_a, phase);
      const double change = measured + 2.0 * kPi * std::round((predicted - measured) / (2.0 * kPi));
      if (std::abs(change) >= kMaxPhaseStep || std::abs(change - predicted) > kPi / 8.0) {
        step = 0.5 * (next - t);
        if (step * length <= 1e-13 * std::max(std::abs(a), std::abs(b))) {
          failure = "the boundary step fell to rounding (a root on the boundary)";
          return false;
        }
        continue;
      }
      winding += change;
      phase_a = phase;
      derivative_a = derivative;
      t = next;
      if (std::abs(change) < kGrowPhaseStep) step = std::min(2.0 * step, 0.25);
    }
    return true;
  }
};

}  // namespace

std::string FeCountRegion::describe() const {
  return fmt::format("{:.6g} <= Re lambda <= {:.6g}, {:.6g} <= Im lambda <= {:.6g} rad/s", re_min,
                     re_max, im_min, im_max);
}

FeArgumentCount count_roots_in_rectangle(const SparseMatrix& K,
                                         const SparseMatrix& C,
                                         const SparseMatrix& M,
                                         const FeCountRegion& region,
                                         const std::vector<Complex>& known,
                                         ComplexBandedLdlt& factor) {
  factor.set_pencil(K, C, M);
  Walker walker{known, factor, 0, {}};
  const std::array<Complex, 4> corners = {
      Complex(region.re_max, region.im_min), Complex(region.re_max, region.im_max),
      Complex(region.re_min, region.im_max), Complex(region.re_min, region.im_min)};
  FeArgumentCount out;
  double phase = 0.0, winding = 0.0;
  Complex derivative;
  bool ok = walker.phase_at(corners[0], phase, derivative);
  for (std::size_t e = 0; ok && e < corners.size(); ++e)
    ok = walker.walk(corners[e], corners[(e + 1) % corners.size()], phase, derivative, winding);
  out.evaluations = walker.evaluations;
  if (!ok) {
    out.failure = walker.failure;
    return out;
  }
  const double turns = winding / (2.0 * kPi);
  out.count = static_cast<int>(std::lround(turns));
  // The sum of changes is 2 pi times an integer up to rounding; anything else is a failure.
  out.ok = std::abs(turns - out.count) < 1e-6 && out.count >= 0;
  if (!out.ok) out.failure = fmt::format("the phase turned by {:.6f} x 2 pi", turns);
  return out;
}

}  // namespace catena::internal
