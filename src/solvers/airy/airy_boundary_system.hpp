// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The 4x4 boundary system of the Airy model, u(0) = w(0) = u(L) = w(L) = 0 (Grinfogel 1984,
/// eq. 16, in real form; docs/explanation/methods/airy.md), with columns (Ai, Bi, cos, sin) for the
/// coefficients (C1, C2, C3, C4) of the slow and fast solutions. Each Airy column is divided by
/// its largest exponential factor and the system is equilibrated by positive factors, so its
/// determinant has the zeros and signs of eq. 16 without overflow.

#include <Eigen/Core>
#include <array>

#include "solvers/airy/airy_model.hpp"

namespace catena::internal {

/// Exponents factored out of the two Airy columns: Ai entries carry e^{-(zeta - ai_ref)} <= 1,
/// Bi entries e^{zeta - bi_ref} <= 1 (zeta is monotone in s, so the ends bound the interior).
struct ColumnExponents {
  double ai_ref = 0.0;
  double bi_ref = 0.0;
};

/// The exponents at frequency omega [rad/s]: zeta at the two ends, smaller and larger.
ColumnExponents column_exponents(const AiryModel& model, double omega);

/// The raw (unequilibrated) rows of one station, columns (Ai, Bi, cos, sin).
struct StationRows {
  std::array<double, 4> w{};  ///< transverse displacement w(s)
  std::array<double, 4> u{};  ///< tangential displacement u(s)
  double slow_ai = 0.0;       ///< scaled Ai(-z(s)): v = C1 slow_ai + C2 slow_bi
  double slow_bi = 0.0;       ///< scaled Bi(-z(s))
};

/// The rows at station s [m], with the statics there: curvature `alpha` [1/m], wave speed
/// `c` = sqrt(T/M) [m/s] and fast phase W(s) = omega int_0^s ds / c.
StationRows station_rows(const AiryModel& model,
                         double omega,
                         double s,
                         double alpha,
                         double c,
                         double phase,
                         const ColumnExponents& exponents);

/// The equilibrated system: matrix = row_scale * raw * diag(column_scale).
struct BoundarySystem {
  Eigen::Matrix4d matrix;
  Eigen::Vector4d column_scale;
  ColumnExponents exponents;
};

/// The boundary system at frequency omega [rad/s].
BoundarySystem boundary_system(const AiryModel& model, double omega);

/// det of the equilibrated boundary system at kL (kL = omega L / sqrt(T0/M)).
double airy_determinant_at(const AiryModel& model, const DimensionlessGroups& groups, double k_l);

}  // namespace catena::internal
