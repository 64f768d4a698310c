// SPDX-License-Identifier: MIT
// The complex roots of the damped frobenius solver: see frobenius_damped_roots.hpp.
#include "solvers/frobenius/frobenius_damped_roots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace catena::internal {

namespace {

using Complex = DampedComplex;
using R = DampedReal;
constexpr double kPi = 3.14159265358979323846;
constexpr double kPhaseTermScale = 1e6;

// The scaled determinant with the drag scaled by s (the homotopy parameter), series cut
// `term_scale` finer; records the work in `out`.
class DampedDeterminant {
 public:
  DampedDeterminant(const DampedSetup& setup, DampedRoots& out) : setup_(setup), out_(out) {}

  Complex operator()(const Complex& lambda, double s, double term_scale = 1.0) {
    DampedSetup scaled = setup_;
    scaled.eta1 *= s;
    scaled.eta2 *= s;
    const DampedMatrix m = damped_boundary_matrix(scaled, lambda, term_scale);
    ++out_.evaluations;
    out_.cancellation = std::max(out_.cancellation, m.cancellation);
    out_.terms = std::max(out_.terms, m.terms);
    out_.centres = std::max(out_.centres, m.centres);
    out_.truncated = out_.truncated || !m.converged;
    return damped_determinant(m.a);
  }

 private:
  const DampedSetup& setup_;
  DampedRoots& out_;
};

struct MullerResult {
  Complex root;
  double last_step = 0.0;  // |last step| / |root|
  bool ok = false;
};

// Muller's method on an analytic f from three points around `guess` (h apart). Written here:
// neither Eigen nor Boost.Math offers a derivative-free complex root finder. Stops when a step
// is below rel_stop |x|, or when the steps stop shrinking below 1e-13 |x| (the rounding floor of
// the determinant), after 40 steps at most; returns the iterate of smallest |f|.
template <class F>
MullerResult muller(F&& f, Complex guess, R h, double rel_stop) {
  Complex x0 = guess - h, x1 = guess + Complex(0, h), x2 = guess;
  Complex f0 = f(x0), f1 = f(x1), f2 = f(x2);
  MullerResult best{x2, 1.0, false};
  R best_f = std::abs(f2);
  R previous_step = std::abs(x2 - x1);
  for (int it = 0; it < 40; ++it) {
    if (f2 == Complex(0)) return {x2, 0.0, true};
    const Complex q = (x2 - x1) / (x1 - x0);
    const Complex A = q * f2 - q * (R(1) + q) * f1 + q * q * f0;
    const Complex B = (R(2) * q + R(1)) * f2 - (R(1) + q) * (R(1) + q) * f1 + q * q * f0;
    const Complex C = (R(1) + q) * f2;
    const Complex root = std::sqrt(B * B - R(4) * A * C);
    const Complex den = std::abs(B + root) >= std::abs(B - root) ? B + root : B - root;
    const Complex step = den == Complex(0) ? (x2 - x1) : Complex(-(x2 - x1) * R(2) * C / den);
    // At the rounding floor the steps stop shrinking (or grow: a noisy determinant would send
    // Muller anywhere): keep the best iterate.
    if (std::abs(step) > previous_step && previous_step < R(1e-11) * std::abs(x2)) {
      best.ok = true;
      best.last_step = static_cast<double>(previous_step / std::abs(x2));
      return best;
    }
    const Complex x3 = x2 + step;
    const R size = std::max(std::abs(x3), R(1e-300));
    const Complex f3 = f(x3);
    const R relative = std::abs(step) / size;
    if (std::abs(f3) <= best_f) {
      best_f = std::abs(f3);
      best = {x3, static_cast<double>(relative), true};
    }
    if (relative <= R(rel_stop)) return {x3, static_cast<double>(relative), true};
    if (relative < R(1e-13) && std::abs(step) > R(0.5) * previous_step) {
      // The floor: the best iterate is known to about the size of these steps.
      best.ok = true;
      best.last_step = std::max(static_cast<double>(relative),
                                static_cast<double>(previous_step / std::abs(x2)));
      return best;
    }
    previous_step = std::abs(step);
    x0 = x1, f0 = f1, x1 = x2, f1 = f2, x2 = x3, f2 = f3;
  }
  best.ok = best.last_step <= 1e3 * rel_stop;
  return best;
}

enum class Track { Oscillating, Real, Failed };

// Continues the undamped root i omega0 along the drag scale s = 0 .. 1 (predictor: linear
// extrapolation in s; corrector: Muller), halving the step when the corrector fails or moves
// further than a quarter of the mode spacing from the prediction. A root whose Im lambda reaches
// 1e-9 |lambda| has met its conjugate on the real axis: Track::Real.
Track continue_root(DampedDeterminant& det, double omega0, double spacing, Complex& lambda) {
  lambda = Complex(0, omega0);
  Complex previous = lambda;
  double s = 0.0, s_previous = 0.0, ds = 1.0;
  while (s < 1.0) {
    const double s_new = std::min(1.0, s + ds);
    const Complex predicted =
        s > 0.0 ? lambda + (lambda - previous) * R((s_new - s) / (s - s_previous)) : lambda;
    // On the way (s < 1) the root is needed to 1e-9 only: series cut 1e3 coarser.
    const auto f = [&](const Complex& z) { return det(z, s_new, s_new < 1.0 ? 1e3 : 1.0); };
    const double stop = s_new < 1.0 ? 1e-9 : 1e-10;
    MullerResult r = muller(f, predicted, R(1e-3 * spacing), stop);
    if (r.ok && r.root.imag() < 0) r.root = std::conj(r.root);  // the conjugate is a root too
    if (!r.ok || std::abs(r.root - predicted) > R(0.25 * spacing)) {
      ds *= 0.5;
      if (ds < 1e-4) return Track::Failed;
      continue;
    }
    previous = lambda;
    s_previous = s;
    lambda = r.root;
    s = s_new;
    if (lambda.imag() <= R(1e-9) * std::abs(lambda)) return Track::Real;
    ds = std::min(1.0 - s, ds * 1.5);
    if (ds <= 0.0) break;
  }
  return Track::Oscillating;
}

// Polishes a root at full drag to the rounding floor, then again with the series cut 1e-3
// finer, and so on (at most three times) until the last correction of each part, plus the last
// Muller step, is within `target` of that part: the estimates of Im lambda and Re lambda, each
// on its own (a small delta needs |error of lambda| below zeta target |lambda|). The estimate is
// the previous level's error; the returned root is the finer one.
DampedRoot polish(
    DampedDeterminant& det, const Complex& guess, double spacing, bool real_root, double target) {
  const R h = std::max(R(1e-8) * std::abs(guess), R(1e-12 * spacing));
  auto level = [&](const Complex& start, double term_scale) {
    MullerResult r =
        muller([&](const Complex& z) { return det(z, 1.0, term_scale); }, start, h, 1e-18);
    if (real_root) r.root = Complex(r.root.real(), 0);  // the determinant is real there
    return r;
  };
  MullerResult a = level(guess, 1.0);
  DampedRoot root;
  double term_scale = 1.0;
  for (int k = 0; k < 3; ++k) {
    term_scale *= 1e-3;
    const MullerResult b = level(a.root, term_scale);
    root.lambda = b.root;
    // Not below the rounding of the determinant's arguments: 1e-18 |lambda| (long double's
    // epsilon is 1.1e-19).
    const R step = R(std::max({a.last_step, b.last_step, 1e-18})) * std::abs(b.root);
    const Complex d = b.root - a.root;
    if (std::abs(d) > R(1e-6) * std::abs(a.root)) {  // not a truncation: keep the coarser root
      root.lambda = a.root;
      root.omega_error = root.delta_error = static_cast<double>(std::abs(d) / std::abs(a.root));
      break;
    }
    root.omega_error =
        real_root ? -1.0
                  : static_cast<double>((std::abs(d.imag()) + step) / std::abs(b.root.imag()));
    root.delta_error = static_cast<double>((std::abs(d.real()) + step) / std::abs(b.root.real()));
    if (!(a.ok && b.ok)) root.delta_error = root.omega_error = 1.0;
    a = b;
    if (std::max(root.omega_error, root.delta_error) <= target) break;
  }
  return root;
}

}  // namespace

namespace {

// The real roots of the determinant on [left, right] (right < 0): sign changes of the real
// determinant on `points` grid points, refined by Illinois regula falsi.
std::vector<double> real_axis_roots(DampedDeterminant& det, double left, double right, int points) {
  const auto g = [&](double x) { return static_cast<double>(det(Complex(x, 0), 1.0).real()); };
  std::vector<double> roots;
  double x0 = left, g0 = g(x0);
  for (int i = 1; i <= points; ++i) {
    const double x1 = left + (right - left) * i / points;
    const double g1 = g(x1);
    if (g0 == 0.0) roots.push_back(x0);
    if ((g0 < 0.0) != (g1 < 0.0) && g0 != 0.0 && g1 != 0.0) {
      int iterations = 0;
      roots.push_back(refine_root(g, x0, x1, g0, g1, 1e-14, iterations));
    }
    x0 = x1;
    g0 = g1;
  }
  return roots;
}

// Change of arg det along the segment a -> b, in steps of at most h that turn the phase by less
// than pi/3 (halved until they do; a true turn must exceed pi to alias). False when a step below
// 1e-7 of the segment still turns more: a root on (or within rounding of) the segment. The phase
// needs few digits: the series are cut at kPhaseTermScale times the solver's term tolerance (1e-9
// at the default), which halves their terms.
bool phase_change(DampedDeterminant& det, Complex a, Complex b, double h, double& total) {
  const R length = std::abs(b - a);
  const Complex unit = (b - a) / length;
  R t = 0;
  Complex fa = det(a, 1.0, kPhaseTermScale);
  R step = std::min(R(h), length);
  while (t < length) {
    const R t_new = std::min(length, t + step);
    const Complex fb = det(a + unit * t_new, 1.0, kPhaseTermScale);
    const R turn = std::arg(fb / fa);
    if (std::abs(turn) > R(kPi / 3)) {
      step *= R(0.5);
      if (step < R(1e-7) * length) return false;
      continue;
    }
    total += static_cast<double>(turn);
    t = t_new;
    fa = fb;
    if (std::abs(turn) < R(kPi / 6)) step = std::min(R(h), step * R(1.5));
  }
  return true;
}

// Zeros of det in the rectangle left < Re lambda < right, |Im lambda| < top, by the argument
// principle. det(conj z) = conj det(z) (real coefficients), so the change of arg along the lower
// half of the boundary equals that along the upper half: the count is (upper change) / pi.
// Returns -1 when a root lies on the boundary or the change is not a multiple of pi.
int argument_count(DampedDeterminant& det, double left, double right, double top, double h) {
  double total = 0.0;
  const Complex corners[4] = {{right, 0}, {right, top}, {left, top}, {left, 0}};
  for (int k = 0; k < 3; ++k)
    if (!phase_change(det, corners[k], corners[k + 1], h, total)) return -1;
  const double n = total / kPi;
  return std::abs(n - std::round(n)) < 0.1 ? static_cast<int>(std::lround(n)) : -1;
}

// Continues undamped roots upward from the lowest until `wanted` complex roots are found (or the
// undamped roots run out); counts those that became real.
void continue_roots(const DampedSetup& setup,
                    const RootSettings& settings,
                    DampedDeterminant& det,
                    double spacing,
                    std::size_t wanted,
                    std::vector<Complex>& complex_roots,
                    int& became_real,
                    DampedRoots& out) {
  std::size_t asked = wanted;
  std::size_t next = 0;
  for (int attempt = 0; attempt < 4 && complex_roots.size() < wanted; ++attempt) {
    const PlaneRoots undamped = find_frequencies(setup.plane, static_cast<int>(asked), settings);
    for (; next < undamped.roots.size() && complex_roots.size() < wanted; ++next) {
      Complex lambda;
      const Track t = continue_root(det, undamped.roots[next].omega, spacing, lambda);
      if (t == Track::Oscillating) complex_roots.push_back(lambda);
      if (t == Track::Real) ++became_real;
      if (t == Track::Failed) {
        out.complete = false;
        out.warnings.push_back(fmt::format(
            "the undamped root Omega = {:.10g} could not be continued to the damped one",
            undamped.roots[next].omega));
      }
    }
    if (undamped.roots.size() < asked) break;  // no more undamped roots to continue
    asked += wanted - complex_roots.size() + 2;
  }
}

}  // namespace

DampedRoots find_damped_roots(const DampedSetup& setup, int count, const RootSettings& settings) {
  DampedRoots out;
  DampedDeterminant det(setup, out);
  const double target = 10.0 * std::max(settings.tolerance, 1e-14);  // the solver's target
  const double spacing = wkb_mode_spacing(setup.plane);
  std::vector<Complex> found;
  int became_real = 0;
  // One root above the modes asked: the top of the counting rectangle lies between them.
  continue_roots(setup, settings, det, spacing, static_cast<std::size_t>(count) + 1, found,
                 became_real, out);
  std::sort(found.begin(), found.end(),
            [](const Complex& a, const Complex& b) { return a.imag() < b.imag(); });
  const std::size_t kept = std::min(found.size(), static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < kept; ++i)
    out.modes.push_back(polish(det, found[i], spacing, false, target));
  for (std::size_t i = 1; i < out.modes.size(); ++i)
    if (std::abs(out.modes[i].lambda - out.modes[i - 1].lambda) <=
        R(1e-8) * std::abs(out.modes[i].lambda)) {
      out.complete = false;
      out.warnings.push_back("two undamped roots were continued to the same damped root");
    }
  // Rectangle: every root has -eta_max <= Re lambda < 0 (the quadratic form of the energies:
  // real roots lie in [-c/m, 0], complex ones have Re lambda = -c/2m), eta_max = max(eta1,
  // eta2/mu) the largest drag per mass.
  const double eta_max = std::max(setup.eta1, setup.eta2 / setup.plane.mu);
  const double left = -1.1 * eta_max - 0.25 * spacing;
  const double right = 0.25 * spacing;
  if (!out.modes.empty()) {
    const double last = static_cast<double>(out.modes.back().lambda.imag());
    out.count_top = found.size() > kept ? 0.5 * (last + static_cast<double>(found[kept].imag()))
                                        : last + 0.5 * spacing;
  }
  // Overdamped roots: where a pair left the complex plane, or the count asks for more roots.
  const int complex_pairs = 2 * static_cast<int>(out.modes.size());
  const long before_count = out.evaluations;
  out.counted =
      out.count_top > 0.0 ? argument_count(det, left, right, out.count_top, 0.5 * spacing) : -1;
  const long count_evaluations = out.evaluations - before_count;
  if (became_real > 0 || out.counted > complex_pairs) {
    for (int points : {128, 512}) {
      const auto real = real_axis_roots(det, left, -1e-9 * spacing, points);
      if (out.counted < 0 || complex_pairs + static_cast<int>(real.size()) >= out.counted ||
          points == 512) {
        for (double x : real)
          out.overdamped.push_back(polish(det, Complex(x, 0), spacing, true, target));
        break;
      }
    }
  }
  std::sort(
      out.overdamped.begin(), out.overdamped.end(),
      [](const DampedRoot& a, const DampedRoot& b) { return a.lambda.real() > b.lambda.real(); });
  out.expected = complex_pairs + static_cast<int>(out.overdamped.size());
  out.notes.push_back(fmt::format(
      "argument principle on Re lambda in [{:.6g}, {:.6g}], |Im lambda| < {:.6g} (Gale units): "
      "{} roots ({} determinant evaluations), {} accounted for ({} complex modes, {} "
      "overdamped); {} undamped roots became overdamped",
      left, right, out.count_top, out.counted, count_evaluations, out.expected, out.modes.size(),
      out.overdamped.size(), became_real));
  return out;
}

}  // namespace catena::internal
