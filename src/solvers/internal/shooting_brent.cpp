// Brent's zero finder: see shooting_brent.hpp.
#include "solvers/internal/shooting_brent.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace catena::internal {

namespace {

// The step of one iteration from b toward the root (inverse quadratic or secant when it is safe
// and shrinks fast enough, else bisection); updates the last two step lengths d and e.
void choose_step(double a, double b, double c, double fa, double fb, double fc, double tol1,
                 double xm, double& d, double& e) {
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

}  // namespace

std::pair<double, double> brent_zero(const std::function<double(double)>& f, double a, double b,
                                     double fa, double fb, double relative_tolerance) {
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
    // An exact zero also ends the search, with the bracket [b, c] as it stands: the end functions
    // are noisy, and an exact zero of one is not trusted as the root (the shooting solver's
    // stress-eps scene at eps = 1e-5 meets an end determinant of exactly 0 about 1e-3 away from
    // the root; the bracket width then carries that uncertainty into the error estimate).
    if (std::abs(xm) <= tol1 || fb == 0.0) break;
    choose_step(a, b, c, fa, fb, fc, tol1, xm, d, e);
    a = b;
    fa = fb;
    b += std::abs(d) > tol1 ? d : std::copysign(tol1, xm);
    fb = f(b);
  }
  return {std::min(b, c), std::max(b, c)};
}

}  // namespace catena::internal
