// SPDX-License-Identifier: MIT
// Tests a hypothesis for the jump of Gale's Table C-3 tension between xi = -0.880 and -0.629
// (h/b = 0, sag 0.70, end xi2 driven tangentially by 0.01 a, wf = 1.32 and 1.36): that on the
// negative side, in the second (ordinary-point) expansion, the sigma-derivatives of U were formed
// as on the positive side, i.e. with |sigma| and derivatives in |xi| (the sign of d/dxi = -d/d|xi|
// lost). Prints, at the printed stations, our U, V, T and the "positive-side formula" V_G, T_G
// (with sigma or |sigma| in the explicit factors of eq. 2.37) beside the printed values.
// Usage: catena_frobenius_c3_hypothesis (built with -DCATENA_BUILD_TOOLS=ON). Uses a private header
// (an exception listed in verification/tools/CMakeLists.txt): it needs the series basis itself.
#include <cmath>
#include <cstdio>
#include <vector>

#include "catena/statics/problem_builders.hpp"
#include "solvers/frobenius/frobenius_catenary.hpp"

using namespace catena;
using namespace catena::internal;
using Real = long double;

int main() {
  const double sag = 0.70;
  const double ab = gale_a_over_b(sag);  // a/b; symmetric cable: sigma2 = sinh(b / 2a)
  const double s2 = std::sinh(0.5 / ab), s1 = -s2;
  const double eta_max = std::sqrt(1.0 + s2 * s2) - 1.0;
  std::printf("xi2 = %.5f\n", eta_max);
  const double printed_t[2][3] = {{4.867, 5.218, 5.132}, {-3.223, -3.422, -3.313}};
  const double printed_v[2][3] = {{0.000, -0.025, -0.051}, {0.000, 0.016, 0.033}};
  int block = 0;
  for (double wf : {1.32, 1.36}) {
    CatenarySeriesSettings settings;
    settings.term_tolerance = 1e-19;
    CatenaryBasis<Real> basis(true, Real(wf), Real(1), eta_max * (1 + 1e-12), settings);
    // Boundary conditions: U = DU = 0 at s1; U = 0.01, DU = 0 at s2.
    std::vector<std::vector<Real>> m(4, std::vector<Real>(4));
    int row = 0;
    for (double s : {s1, s2}) {
      const auto v = basis.evaluate(Real(s), 1);
      for (int d = 0; d < 2; ++d, ++row)
        for (int j = 0; j < 4; ++j) m[row][j] = v.value[j][d];
    }
    const std::vector<Real> c = solve_dense(m, {0, 0, Real(0.01), 0});
    std::printf(
        "wf = %.2f\n  xi       U        V      T     | V_G     T_G(sigma) T_G(|sigma|) | printed "
        "V, T\n",
        wf);
    int k = 0;
    for (double xi : {-1.383, -1.132, -0.880, -0.629}) {
      const double x = xi == -1.383 ? -eta_max : xi;
      const double sigma = gale_sigma_from_xi(x);
      const double eta = std::abs(x), C = 1.0 + eta, q = sigma * sigma;
      const auto v = basis.evaluate(Real(sigma), 3);
      Real d[4] = {0, 0, 0, 0};
      for (int j = 0; j < 4; ++j)
        for (int n = 0; n < 4; ++n) d[n] += c[j] * v.value[j][n];
      const double A = (3 + 4 * q) * C + wf * wf * std::pow(C, 4);
      const double T = (double)((sigma / C) * d[0] - A * d[1] - 5 * sigma * C * C * C * d[2] -
                                std::pow(C, 5) * d[3]);
      // eta-derivatives F' , F'', F''' of U on this side (sigma < 0): invert the chain rule.
      const double F1 = (double)d[1] * C / sigma;
      const double F2 = ((double)d[2] - F1 / (C * C * C)) * C * C / q;
      const double F3 = ((double)d[3] / sigma - 3 * F2 / std::pow(C, 4) + 3 * F1 / std::pow(C, 5)) *
                        C * C * C / q;
      const double as = std::abs(sigma);
      const double DUg = as / C * F1;
      const double D2Ug = q / (C * C) * F2 - F1 / (C * C * C);
      const double D3Ug =
          as * (q / (C * C * C) * F3 - 3 * F2 / std::pow(C, 4) - 3 * F1 / std::pow(C, 5));
      const double Tg1 = (sigma / C) * (double)d[0] - A * DUg - 5 * sigma * C * C * C * D2Ug -
                         std::pow(C, 5) * D3Ug;
      const double Tg2 =
          (as / C) * (double)d[0] - A * DUg - 5 * as * C * C * C * D2Ug - std::pow(C, 5) * D3Ug;
      std::printf("  %6.3f %8.4f %8.4f %7.4f | %7.4f %8.4f %8.4f", xi, (double)d[0],
                  (double)(C * C * d[1]), T, C * C * DUg, Tg1, Tg2);
      if (k < 3) std::printf("   | %6.3f %6.3f", printed_v[block][k], printed_t[block][k]);
      std::printf("\n");
      ++k;
    }
    ++block;
  }
  return 0;
}
