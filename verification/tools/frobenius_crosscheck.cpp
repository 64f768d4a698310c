// SPDX-License-Identifier: MIT
// Independent check of the frobenius solver's frequencies: direct numerical integration of the
// first-order system in sigma (no series, no change of variable), Boost.Odeint Runge-Kutta-Fehlberg
// 7(8) at tight tolerances, and a scan of the shooting determinant counting its sign changes from
// Omega = 0 (so the mode index is counted independently too). The equations are in
// common/sigma_ode.hpp (shared with the other frobenius tools).
// Usage (built with -DCATENA_BUILD_TOOLS=ON):
//        catena_frobenius_crosscheck <xi1> <xi2> <inplane 0/1> <modes> [rel_tol]
//        catena_frobenius_crosscheck <xi1> <xi2> forced <wf>   (end xi2 driven tangentially by 0.01
//        a, xi1 fixed: prints max |T|/H over 2000 steps and T/H at both ends)
// Prints the Omega of each mode. Used for the report's evidence on Table B-3/B-4 disagreements and
// for the deep-sag values beyond the thesis.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "catena/statics/problem_builders.hpp"
#include "common/sigma_ode.hpp"

namespace {

using catena_tools::SigmaOdeSettings;

// Tolerances rel_tol (the optional argument, 1e-12 by default) and abs_tol = rel_tol / 100.
SigmaOdeSettings settings_for(double rel_tol) {
  SigmaOdeSettings settings;
  settings.rel_tol = rel_tol;
  settings.abs_tol = rel_tol * 1e-2;
  return settings;
}

// Forced: end xi2 driven tangentially by 0.01 a, xi1 clamped; prints max |T| over 2000 steps.
int print_forced_response(double s1, double s2, double wf) {
  const SigmaOdeSettings settings = settings_for(1e-12);
  const double w2 = std::pow(wf, 2);
  const auto a = catena_tools::integrate_sigma_ode<4>({0, 0, 1, 0}, s1, s2, w2, settings);
  const auto b = catena_tools::integrate_sigma_ode<4>({0, 0, 0, 1}, s1, s2, w2, settings);
  // alpha a + beta b: u(s2) = 0.01, w(s2) = 0.
  const double det = a[0] * b[1] - a[1] * b[0];
  const double alpha = (0.01 * b[1]) / det, beta = (-0.01 * a[1]) / det;
  std::array<double, 4> y{0, 0, alpha, beta};
  double smax = std::abs(beta), s = s1;
  const int steps = 2000;
  for (int i = 0; i < steps; ++i) {
    const double next = s1 + (s2 - s1) * (i + 1) / steps;
    y = catena_tools::integrate_sigma_ode<4>(y, s, next, w2, settings);
    s = next;
    smax = std::max(smax, std::abs(y[3]));
  }
  std::printf("max|T| %.6f  T(xi1) %.6f  T(xi2) %.6f  u(xi2) %.6f w(xi2) %.2e\n", smax, beta, y[3],
              y[0], y[1]);
  return 0;
}

// Scans the normalised determinant from Omega = 0 in steps of 1/50 of the WKB mode spacing and
// bisects every sign change: the mode index is counted, not assumed.
int print_natural_frequencies(
    double s1, double s2, bool inplane, int modes, const SigmaOdeSettings& settings) {
  double integral = 0.0;
  for (int i = 0; i <= 400; ++i)
    integral += (i == 0 || i == 400 ? 0.5 : 1.0) /
                std::sqrt(std::sqrt(1.0 + std::pow(s1 + (s2 - s1) * i / 400.0, 2)));
  integral *= (s2 - s1) / 400.0;
  const double step = 0.02 * M_PI / integral;
  auto det = [&](double omega) {
    return catena_tools::clamped_end_determinant(inplane, s1, s2, omega, settings, true);
  };
  double x0 = 0.01 * step, f0 = det(x0);
  int found = 0;
  while (found < modes) {
    const double x1 = x0 + step, f1 = det(x1);
    if ((f0 < 0) != (f1 < 0)) {
      double lo = x0, hi = x1, flo = f0;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi), fm = det(mid);
        if ((fm < 0) == (flo < 0)) {
          lo = mid;
          flo = fm;
        } else
          hi = mid;
      }
      std::printf("%d %.12f\n", ++found, 0.5 * (lo + hi));
    }
    x0 = x1;
    f0 = f1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s xi1 xi2 inplane modes [rel_tol]\n       %s xi1 xi2 forced wf\n",
                 argv[0], argv[0]);
    return 2;
  }
  const double s1 = catena::gale_sigma_from_xi(std::atof(argv[1]));
  const double s2 = catena::gale_sigma_from_xi(std::atof(argv[2]));
  if (std::string(argv[3]) == "forced") return print_forced_response(s1, s2, std::atof(argv[4]));
  const bool inplane = std::atoi(argv[3]) != 0;
  const int modes = std::atoi(argv[4]);
  return print_natural_frequencies(s1, s2, inplane, modes,
                                   settings_for(argc > 5 ? std::atof(argv[5]) : 1e-12));
}
