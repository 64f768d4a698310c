// SPDX-License-Identifier: MIT
// Roots of the damped boundary determinant: see shooting_damped_roots.hpp.
#include "solvers/shooting/shooting_damped_roots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/core/types.hpp"
#include "solvers/shooting/shooting_brent.hpp"

namespace catena::internal {

namespace {

using Complex = std::complex<double>;

// D's values on the scale of `reference` (Muller's divided differences need one scale).
Complex on_scale(const DampedValue& value, double reference) {
  return value.determinant * std::exp(value.log_scale - reference);
}

// A root with |Im| below this fraction of |lambda| is real (the homotopy's loose tolerance leaves
// an imaginary part of its size); a root lost within kNearRealAxis of the axis met its conjugate.
constexpr double kRealAxis = 1e-5;
constexpr double kNearRealAxis = 0.1;

// The principal change of argument from a to b, in (-pi, pi].
double arg_change(Complex a, Complex b) { return std::arg(b / a); }

}  // namespace

MullerResult muller_root(const DampedFunction& f,
                         Complex guess,
                         double spread,
                         double tolerance,
                         double factor,
                         double radius,
                         int max_iterations) {
  MullerResult result;
  Complex x[3] = {guess + spread, guess + Complex(0.0, spread), guess};
  DampedValue v[3] = {f(x[0], factor), f(x[1], factor), f(x[2], factor)};
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    const double reference = v[2].log_scale;
    const Complex f0 = on_scale(v[0], reference), f1 = on_scale(v[1], reference);
    const Complex f2 = v[2].determinant;
    const Complex h1 = x[1] - x[0], h2 = x[2] - x[1];
    const Complex d1 = (f1 - f0) / h1, d2 = (f2 - f1) / h2;
    const Complex a = (d2 - d1) / (h2 + h1);
    const Complex b = a * h2 + d2;
    const Complex root = std::sqrt(b * b - 4.0 * f2 * a);
    const Complex denominator = std::abs(b + root) >= std::abs(b - root) ? b + root : b - root;
    if (!(std::abs(denominator) > 0.0) || !std::isfinite(std::abs(f2))) break;
    const Complex step = -2.0 * f2 / denominator;
    const Complex next = x[2] + step;
    result.iterations = iteration;
    if (!(std::abs(next - guess) <= radius)) break;
    if (std::abs(step) <= tolerance * std::abs(next) || f2 == 0.0) {
      result.converged = true;
      result.root = f2 == 0.0 ? x[2] : next;
      result.slope = b + 2.0 * a * (result.root - x[2]);
      result.slope_log_scale = reference;
      return result;
    }
    x[0] = x[1], x[1] = x[2], x[2] = next;
    v[0] = v[1], v[1] = v[2], v[2] = f(next, factor);
  }
  result.root = x[2];
  return result;
}

MullerResult secant_polish(const DampedFunction& f,
                           Complex start,
                           Complex slope,
                           double slope_log_scale,
                           double tolerance,
                           double factor,
                           int max_iterations) {
  MullerResult result;
  Complex x0 = start;
  DampedValue v0 = f(x0, factor);
  const double reference = v0.log_scale;
  Complex f0 = v0.determinant;
  Complex d = slope * std::exp(slope_log_scale - reference);
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    if (!(std::abs(d) > 0.0) || !std::isfinite(std::abs(f0))) break;
    const Complex step = -f0 / d;
    const Complex x1 = x0 + step;
    result.iterations = iteration;
    if (std::abs(step) <= tolerance * std::abs(x1) || f0 == 0.0) {
      result.converged = true;
      result.root = f0 == 0.0 ? x0 : x1;
      result.slope = d;
      result.slope_log_scale = reference;
      return result;
    }
    const Complex f1 = on_scale(f(x1, factor), reference);
    d = (f1 - f0) / step;
    x0 = x1, f0 = f1;
  }
  result.root = x0;
  return result;
}

ContinuedRoot continue_root(const DampedFunction& f,
                            const std::function<void(double)>& set_scale,
                            Complex start,
                            double gap,
                            const ContinuationSettings& settings) {
  ContinuedRoot out;
  double t = 0.0, t_previous = 0.0, h = 1.0;
  Complex lambda = start, previous = start;
  bool has_previous = false;
  while (t < 1.0) {
    const double t_next = std::min(1.0, t + h);
    const Complex predicted =
        has_previous ? lambda + (lambda - previous) * ((t_next - t) / (t - t_previous)) : lambda;
    const double radius = settings.radius_fraction * gap;
    set_scale(t_next);
    // Secant steps from the prediction with the last root's slope (one shot a step); Muller's
    // method from three points when they fail or leave the radius.
    MullerResult step;
    if (has_previous) {
      step = secant_polish(f, predicted, out.slope, out.slope_log_scale, settings.loose_tolerance,
                           settings.loose_factor);
      step.converged = step.converged && std::abs(step.root - predicted) <= radius;
    }
    if (!step.converged) {
      step = muller_root(f, predicted, 1e-3 * radius, settings.loose_tolerance,
                         settings.loose_factor, radius, t_next >= 1.0 ? 40 : 15);
    }
    if (step.converged && t_next >= 1.0 && settings.polish) {
      step = secant_polish(f, step.root, step.slope, step.slope_log_scale, settings.tolerance, 1.0);
      out.polished = step.converged;
    }
    if (step.converged) {  // within the radius of the prediction (muller_root)
      previous = lambda, t_previous = t, has_previous = true;
      lambda = step.root, t = t_next;
      out.slope = step.slope, out.slope_log_scale = step.slope_log_scale;
      ++out.steps;
      if (step.iterations <= 6) h = std::min(2.0 * h, 1.0);
      if (std::abs(lambda.imag()) <= kRealAxis * std::abs(lambda)) break;
      continue;
    }
    h /= 4.0;
    if (h < settings.min_step && std::abs(lambda.imag()) <= kNearRealAxis * std::abs(lambda)) {
      // Near the real axis the root meets its conjugate (a double root, where Muller slows down
      // and the path turns by 90 degrees): what it becomes is found on the real axis.
      out.ok = out.went_real = true;
      out.root = lambda;
      return out;
    }
    if (h < settings.min_step) {
      out.reason = fmt::format(
          "the root continued from {:.10g}i 1/s was lost at damping scale {:.6g} (near {:.10g} "
          "{:+.10g}i 1/s): Muller did not converge within {:.3g} 1/s of the prediction",
          start.imag(), t, lambda.real(), lambda.imag(), radius);
      out.root = lambda;
      return out;
    }
  }
  out.ok = true;
  out.root = lambda;
  out.went_real = std::abs(lambda.imag()) <= kRealAxis * std::abs(lambda);
  return out;
}

namespace {

// Adds the change of arg D along the segment from a to b (values fa, fb), bisected until each
// piece changes the argument by less than pi/4.
bool add_arg_change(const DampedFunction& f,
                    Complex a,
                    Complex b,
                    Complex fa,
                    Complex fb,
                    double factor,
                    int depth,
                    RootCount& count,
                    double& total) {
  const double change = arg_change(fa, fb);
  if (std::abs(change) < 0.25 * kPi) {
    total += change;
    return true;
  }
  if (depth > 24) {
    count.reason = fmt::format(
        "the argument of D still turns by {:.3g} rad between {:.10g}{:+.10g}i and "
        "{:.10g}{:+.10g}i 1/s after 24 bisections (a root on the contour)",
        change, a.real(), a.imag(), b.real(), b.imag());
    return false;
  }
  const Complex middle = 0.5 * (a + b);
  const Complex fm = f(middle, factor).determinant;
  ++count.evaluations;
  return add_arg_change(f, a, middle, fa, fm, factor, depth + 1, count, total) &&
         add_arg_change(f, middle, b, fm, fb, factor, depth + 1, count, total);
}

}  // namespace

RootCount count_roots(
    const DampedFunction& f, double sigma, double delta_max, double top, double factor) {
  RootCount count;
  const Complex corners[4] = {{sigma, 0.0}, {sigma, top}, {-delta_max, top}, {-delta_max, 0.0}};
  constexpr int kPiecesPerEdge = 8;
  double total = 0.0;
  Complex previous = corners[0];
  Complex f_previous = f(previous, factor).determinant;
  ++count.evaluations;
  for (int edge = 0; edge < 3; ++edge) {
    for (int j = 1; j <= kPiecesPerEdge; ++j) {
      const Complex point =
          corners[edge] + (corners[edge + 1] - corners[edge]) * (double(j) / kPiecesPerEdge);
      const Complex value = f(point, factor).determinant;
      ++count.evaluations;
      if (!(std::abs(value) > 0.0) || !std::isfinite(std::abs(value))) {
        count.reason = fmt::format("D is {} at {:.10g}{:+.10g}i 1/s on the contour",
                                   std::abs(value), point.real(), point.imag());
        return count;
      }
      if (!add_arg_change(f, previous, point, f_previous, value, factor, 0, count, total)) {
        return count;
      }
      previous = point, f_previous = value;
    }
  }
  // D is real at both ends: the change is a multiple of pi up to rounding.
  const double turns = total / kPi;
  count.roots = static_cast<int>(std::lround(turns));
  count.ok = std::abs(turns - count.roots) < 0.01;
  if (!count.ok) count.reason = fmt::format("arg D changed by {:.6g} pi, not a multiple", turns);
  return count;
}

std::vector<double> real_roots(
    const DampedFunction& f, double delta_max, int samples, double tolerance, double factor) {
  const double reference = f(Complex(0.0, 0.0), factor).log_scale;
  const auto real_value = [&](double x) {
    const DampedValue value = f(Complex(x, 0.0), factor);
    return value.determinant.real() * std::exp(value.log_scale - reference);
  };
  const auto tight_value = [&](double x) {
    const DampedValue value = f(Complex(x, 0.0), 1.0);
    return value.determinant.real() * std::exp(value.log_scale - reference);
  };
  std::vector<double> roots;
  // Down from 0, where D is the static problem's determinant (not zero).
  double b = 0.0, fb = real_value(0.0);
  for (int j = 1; j <= samples; ++j) {
    const double a = -delta_max * j / samples;
    const double fa = real_value(a);
    if (fa * fb < 0.0) {
      const double fa_tight = tight_value(a), fb_tight = tight_value(b);
      if (fa_tight * fb_tight < 0.0) {
        const auto bracket = brent_zero(tight_value, a, b, fa_tight, fb_tight, tolerance);
        roots.push_back(0.5 * (bracket.first + bracket.second));
      }
    }
    b = a, fb = fa;
  }
  return roots;
}

}  // namespace catena::internal
