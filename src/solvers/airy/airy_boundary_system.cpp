// SPDX-License-Identifier: MIT
// The 4x4 boundary system of the Airy model: station rows, column exponents, equilibration.
#include "solvers/airy/airy_boundary_system.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "solvers/airy/airy_functions.hpp"

namespace catena::internal {

ColumnExponents column_exponents(const AiryModel& model, double omega) {
  auto zeta = [&](double s) {
    const double x = airy_argument(model, omega, s);
    return x > 0.0 ? 2.0 / 3.0 * x * std::sqrt(x) : 0.0;
  };
  const double z0 = zeta(0.0);
  const double z1 = zeta(model.length);
  return {std::min(z0, z1), std::max(z0, z1)};
}

StationRows station_rows(const AiryModel& model,
                         double omega,
                         double s,
                         double alpha,
                         double c,
                         double phase,
                         const ColumnExponents& exponents) {
  const ScaledAiry airy = scaled_airy(airy_argument(model, omega, s));
  const double ai_factor = std::exp(-(airy.zeta - exponents.ai_ref));
  const double bi_factor = std::exp(airy.zeta - exponents.bi_ref);
  const double cos_w = std::cos(phase);
  const double sin_w = std::sin(phase);
  const double fast_w = 1.0 / std::sqrt(c);
  const double fast_u = alpha * std::sqrt(c) / omega;
  StationRows rows;
  rows.slow_ai = airy.ai * ai_factor;
  rows.slow_bi = airy.bi * bi_factor;
  // Slow part: w = -h alpha v, u = -v' = kappa (C1 Ai'(-z) + C2 Bi'(-z)); fast part: eqs. (7)-(8).
  rows.w = {-model.h * alpha * rows.slow_ai, -model.h * alpha * rows.slow_bi, fast_w * cos_w,
            fast_w * sin_w};
  rows.u = {model.kappa * airy.ai_prime * ai_factor, model.kappa * airy.bi_prime * bi_factor,
            fast_u * sin_w, -fast_u * cos_w};
  return rows;
}

BoundarySystem boundary_system(const AiryModel& model, double omega) {
  BoundarySystem system;
  system.exponents = column_exponents(model, omega);
  const double ends[2] = {0.0, model.length};
  const double phases[2] = {0.0, omega * model.travel_time};
  for (int i = 0; i < 2; ++i) {
    const StationRows rows = station_rows(model, omega, ends[i], model.alpha_end[i], model.c_end[i],
                                          phases[i], system.exponents);
    for (int j = 0; j < 4; ++j) {
      system.matrix(2 * i, j) = rows.w[j];
      system.matrix(2 * i + 1, j) = rows.u[j];
    }
  }
  // Equilibrate columns then rows by their largest entries (positive factors: the zero set and
  // the sign of the determinant are unchanged).
  for (int j = 0; j < 4; ++j) {
    const double largest = system.matrix.col(j).cwiseAbs().maxCoeff();
    system.column_scale[j] = largest > 0.0 ? 1.0 / largest : 1.0;
    system.matrix.col(j) *= system.column_scale[j];
  }
  for (int i = 0; i < 4; ++i) {
    const double largest = system.matrix.row(i).cwiseAbs().maxCoeff();
    if (largest > 0.0) system.matrix.row(i) /= largest;
  }
  return system;
}

double airy_determinant_at(const AiryModel& model, const DimensionlessGroups& groups, double k_l) {
  const double omega = groups.omega_from_k_l_over_pi(k_l / kPi);
  return boundary_system(model, omega).matrix.determinant();
}

}  // namespace catena::internal
