// SPDX-License-Identifier: MIT
// Brent's zero finder: see shooting_brent.hpp.
#include "solvers/shooting/shooting_brent.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace catena::internal {

namespace {

// Exact zeros met in a row before the search settles for the bracket it has.
constexpr int kMaxZeroDepth = 8;

// The step of one iteration from b toward the root (inverse quadratic or secant when it is safe
// and shrinks fast enough, else bisection); updates the last two step lengths d and e.
void choose_step(double a,
                 double b,
                 double c,
                 double fa,
                 double fb,
                 double fc,
                 double tol1,
                 double xm,
                 double& d,
                 double& e) {
  if (std::abs(e) >= tol1 && std::abs(fa) > std::abs(fb)) {
    double p, q;
    const double s = fb / fa;
    if (a == c) {
      p = 2.0 * xm * s;
      q = 1.0 - s;
    } else {
      const double qa = fa / fc, r = fb / fc;
      p = s * (2.0 * xm * qa * (qa - r) - (b - a) * (r - 1.0));
      q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
    }
    if (p > 0.0) q = -q;
    p = std::abs(p);
    if (2.0 * p < std::min(3.0 * xm * q - std::abs(tol1 * q), std::abs(e * q))) {
      e = d;
      d = p / q;
      return;
    }
  }
  d = xm;
  e = d;
}

std::pair<double, double> brent_zero_at_depth(const std::function<double(double)>& f,
                                              double a,
                                              double b,
                                              double fa,
                                              double fb,
                                              double relative_tolerance,
                                              int depth);

bool same_sign(double x, double y) { return (x > 0.0 && y > 0.0) || (x < 0.0 && y < 0.0); }

// An iterate b where f is exactly zero, inside the strict bracket (a, c) (fa, fc nonzero and of
// opposite signs). The end functions are noisy, so the zero is tested rather than trusted: f is
// probed at half the tolerance on either side of b. Probes that carry the signs of their sides
// bracket the root to the tolerance; a probe with the other side's sign shows the zero to be
// spurious (the stress-eps scene at eps = 1e-5 meets an end determinant of exactly 0 about 1e-3
// away from the root) and the search goes on in the strict bracket it leaves. Probes that are
// zero too are moved out tenfold; when that leaves (a, c), the bracket is [a, c] as it stands.
std::pair<double, double> resolve_exact_zero(const std::function<double(double)>& f,
                                             double a,
                                             double fa,
                                             double b,
                                             double c,
                                             double fc,
                                             double relative_tolerance,
                                             int depth) {
  const double toward_c = c > a ? 1.0 : -1.0;
  for (double delta = 0.5 * relative_tolerance * std::abs(b);
       delta < std::abs(c - a) && depth < kMaxZeroDepth; delta *= 10.0) {
    const double qa = b - toward_c * delta, qc = b + toward_c * delta;
    if ((qa - a) * toward_c <= 0.0 || (c - qc) * toward_c <= 0.0) break;
    const double fqa = f(qa), fqc = f(qc);
    if (same_sign(fqa, fa) && same_sign(fqc, fc)) return {std::min(qa, qc), std::max(qa, qc)};
    if (same_sign(fqc, fa))
      return brent_zero_at_depth(f, qc, c, fqc, fc, relative_tolerance, depth + 1);
    if (same_sign(fqa, fc))
      return brent_zero_at_depth(f, a, qa, fa, fqa, relative_tolerance, depth + 1);
  }
  return {std::min(a, c), std::max(a, c)};
}

std::pair<double, double> brent_zero_at_depth(const std::function<double(double)>& f,
                                              double a,
                                              double b,
                                              double fa,
                                              double fb,
                                              double relative_tolerance,
                                              int depth) {
  double c = a, fc = fa;
  double d = b - a, e = d;
  for (int iteration = 0; iteration < 300; ++iteration) {
    if ((fb > 0.0 && fc > 0.0) || (fb < 0.0 && fc < 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol1 = 2.0 * std::numeric_limits<double>::epsilon() * std::abs(b) +
                        0.25 * relative_tolerance * std::abs(b);
    const double xm = 0.5 * (c - b);
    if (std::abs(xm) <= tol1) break;
    choose_step(a, b, c, fa, fb, fc, tol1, xm, d, e);
    a = b;
    fa = fb;
    b += std::abs(d) > tol1 ? d : std::copysign(tol1, xm);
    fb = f(b);
    // a (the last iterate) and c bracket b strictly: fa != 0 (else the search had stopped).
    if (fb == 0.0) return resolve_exact_zero(f, a, fa, b, c, fc, relative_tolerance, depth);
  }
  return {std::min(b, c), std::max(b, c)};
}

}  // namespace

std::pair<double, double> brent_zero(const std::function<double(double)>& f,
                                     double a,
                                     double b,
                                     double fa,
                                     double fb,
                                     double relative_tolerance) {
  // An end given exactly at the root is the root (a shot accurate to rounding can land there).
  if (fa == 0.0) return {a, a};
  if (fb == 0.0) return {b, b};
  return brent_zero_at_depth(f, a, b, fa, fb, relative_tolerance, 0);
}

}  // namespace catena::internal
