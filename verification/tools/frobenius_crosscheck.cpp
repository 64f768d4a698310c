// Independent check of the frobenius solver's frequencies: direct numerical integration of the
// first-order system in sigma (no series, no change of variable), Boost.Odeint Runge-Kutta-Fehlberg
// 7(8) at tight tolerances, and a scan of the shooting determinant counting its sign changes from
// Omega = 0 (so the mode index is counted independently too). Equations (units a, H; C = sqrt(1+s^2)):
//   u' = w/C^2,  w' = phi - u/C^2,  tau' = phi/C - W2 u,  (C phi)' = -tau/C^2 - mu W2 w
//   out of plane: v' = p/C, p' = -mu W2 v.
// Usage: frobenius_crosscheck <xi1> <xi2> <inplane 0/1> <modes> [rel_tol]
//        frobenius_crosscheck <xi1> <xi2> forced <wf>   (end xi2 driven tangentially by 0.01 a, xi1 fixed:
//        prints max |T|/H over 2000 steps and T/H at both ends)
// Prints the Omega of each mode. Used for the report's evidence on Table B-3/B-4 disagreements and
// for the deep-sag values beyond the thesis.
#include <boost/numeric/odeint.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "catena/statics/problem_builders.hpp"

namespace {

double g_tol = 1e-12;

template <int N>
std::array<double, N> integrate(std::array<double, N> y, double s1, double s2, double w2, double mu) {
  using namespace boost::numeric::odeint;
  auto rhs = [w2, mu](const std::array<double, N>& x, std::array<double, N>& dx, double s) {
    const double C = std::sqrt(1.0 + s * s);
    if constexpr (N == 4) {
      const double u = x[0], w = x[1], phi = x[2], tau = x[3];
      dx[0] = w / (C * C);
      dx[1] = phi - u / (C * C);
      dx[3] = phi / C - w2 * u;
      dx[2] = (-tau / (C * C) - mu * w2 * w - (s / C) * phi) / C;
    } else {
      dx[0] = x[1] / C;
      dx[1] = -mu * w2 * x[0];
    }
  };
  integrate_adaptive(make_controlled(g_tol * 1e-2, g_tol, runge_kutta_fehlberg78<std::array<double, N>>()), rhs, y, s1,
                     s2, (s2 - s1) / 200.0);
  return y;
}

double shooting_det(bool inplane, double s1, double s2, double omega, double mu) {
  const double w2 = omega * omega;
  if (inplane) {
    const auto a = integrate<4>({0, 0, 1, 0}, s1, s2, w2, mu);
    const auto b = integrate<4>({0, 0, 0, 1}, s1, s2, w2, mu);
    const double na = std::hypot(std::hypot(a[0], a[1]), std::hypot(a[2], a[3]));
    const double nb = std::hypot(std::hypot(b[0], b[1]), std::hypot(b[2], b[3]));
    return (a[0] * b[1] - a[1] * b[0]) / (na * nb);
  }
  const auto a = integrate<2>({0, 1}, s1, s2, w2, mu);
  return a[0] / std::hypot(a[0], a[1]);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s xi1 xi2 inplane modes [rel_tol]\n", argv[0]);
    return 2;
  }
  const double s1 = catena::gale_sigma_from_xi(std::atof(argv[1]));
  const double s2 = catena::gale_sigma_from_xi(std::atof(argv[2]));
  if (std::string(argv[3]) == "forced") {
    const double w2 = std::pow(std::atof(argv[4]), 2);
    const auto a = integrate<4>({0, 0, 1, 0}, s1, s2, w2, 1.0);
    const auto b = integrate<4>({0, 0, 0, 1}, s1, s2, w2, 1.0);
    // alpha a + beta b: u(s2) = 0.01, w(s2) = 0.
    const double det = a[0] * b[1] - a[1] * b[0];
    const double alpha = (0.01 * b[1]) / det, beta = (-0.01 * a[1]) / det;
    std::array<double, 4> y{0, 0, alpha, beta};
    double smax = std::abs(beta), s = s1;
    const int steps = 2000;
    for (int i = 0; i < steps; ++i) {
      const double next = s1 + (s2 - s1) * (i + 1) / steps;
      y = integrate<4>(y, s, next, w2, 1.0);
      s = next;
      smax = std::max(smax, std::abs(y[3]));
    }
    std::printf("max|T| %.6f  T(xi1) %.6f  T(xi2) %.6f  u(xi2) %.6f w(xi2) %.2e\n", smax, beta, y[3], y[0], y[1]);
    return 0;
  }
  const bool inplane = std::atoi(argv[3]) != 0;
  const int modes = std::atoi(argv[4]);
  if (argc > 5) g_tol = std::atof(argv[5]);
  double integral = 0.0;
  for (int i = 0; i <= 400; ++i) integral += (i == 0 || i == 400 ? 0.5 : 1.0) / std::sqrt(std::sqrt(1.0 + std::pow(s1 + (s2 - s1) * i / 400.0, 2)));
  integral *= (s2 - s1) / 400.0;
  const double step = 0.02 * M_PI / integral;
  double x0 = 0.01 * step, f0 = shooting_det(inplane, s1, s2, x0, 1.0);
  int found = 0;
  while (found < modes) {
    const double x1 = x0 + step, f1 = shooting_det(inplane, s1, s2, x1, 1.0);
    if ((f0 < 0) != (f1 < 0)) {
      double lo = x0, hi = x1, flo = f0;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi), fm = shooting_det(inplane, s1, s2, mid, 1.0);
        if ((fm < 0) == (flo < 0)) { lo = mid; flo = fm; } else hi = mid;
      }
      std::printf("%d %.12f\n", ++found, 0.5 * (lo + hi));
    }
    x0 = x1;
    f0 = f1;
  }
  return 0;
}
