// SPDX-License-Identifier: MIT
// One piece of elastic catenary in closed form: see catenary_segment.hpp.
#include "statics/internal/catenary_segment.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace catena::internal {
namespace {

// A weightless piece is a straight bar along (H, V)/T stretched by T/EA: r(s) = s (1 + T/EA) t.
Vec2 straight_offset(const CableProperties& cable, double H, double V, double s) {
  const double T = std::hypot(H, V);
  const double stretch = s * (1.0 / T + inverse_stiffness(cable));
  return {H * stretch, V * stretch};
}

// d r(L) / d(H, V) of the straight bar: L/T^3 [[V^2, -H V], [-H V, H^2]] + L/EA I.
Eigen::Matrix2d straight_jacobian(const CableProperties& cable, double H, double V) {
  const double L = cable.length_m;
  const double T = std::hypot(H, V);
  const double scale = L / (T * T * T);
  const double compliance_l = L * inverse_stiffness(cable);
  Eigen::Matrix2d J;
  J << scale * V * V + compliance_l, -scale * H * V, -scale * H * V, scale * H * H + compliance_l;
  return J;
}

}  // namespace

// asinh(V/H) - asinh(V_A/H) = asinh(D), with D written so that neither branch cancels:
// same signs: D = W0 s (V + V_A) / (V T_A + V_A T); otherwise D = (V T_A - V_A T) / H^2.
double asinh_difference(double H, double V_A, double V, double T_A, double T, double W0s) {
  if (V * V_A > 0.0) return std::asinh(W0s * (V + V_A) / (V * T_A + V_A * T));
  return std::asinh((V * T_A - V_A * T) / (H * H));
}

Vec2 offset(const CableProperties& cable, double H, double V_A, double s) {
  const double W0 = cable.weight_n_per_m;
  if (W0 == 0.0) return straight_offset(cable, H, V_A, s);
  const double V = V_A + W0 * s;
  const double T_A = std::hypot(H, V_A);
  const double T = std::hypot(H, V);
  const double compliance = inverse_stiffness(cable);
  double x = H * s * compliance;
  double z = (V_A * s + 0.5 * W0 * s * s) * compliance;
  if (H > 0.0) x += (H / W0) * asinh_difference(H, V_A, V, T_A, T, W0 * s);
  // (T - T_A)/W0 = s (V + V_A)/(T + T_A): exact, and finite for H = 0.
  if (T + T_A > 0.0) z += s * (V + V_A) / (T + T_A);
  return {x, z};
}

// Jacobian of r(L) with respect to (H, V_A); entries written without cancellation.
Eigen::Matrix2d offset_jacobian(const CableProperties& cable, double H, double V_A) {
  const double L = cable.length_m;
  const double W0 = cable.weight_n_per_m;
  if (W0 == 0.0) return straight_jacobian(cable, H, V_A);
  const double compliance_l = L * inverse_stiffness(cable);
  const double V_B = V_A + W0 * L;
  const double T_A = std::hypot(H, V_A);
  const double T_B = std::hypot(H, V_B);
  // dx/dV_A = dz/dH = (H/W0)(1/T_B - 1/T_A) = -H L (V_A + V_B) / ((T_A + T_B) T_A T_B).
  const double cross = -H * L * (V_A + V_B) / ((T_A + T_B) * T_A * T_B);
  // dz/dV_A = L/EA + int H^2/T^3 ds = L/EA + (V_B/T_B - V_A/T_A)/W0.
  double dz_dv;
  if (V_A * V_B > 0.0) {
    dz_dv = H * H * L * (V_A + V_B) / ((V_B * T_A + V_A * T_B) * T_A * T_B);
  } else {
    dz_dv = (V_B * T_A - V_A * T_B) / (W0 * T_A * T_B);
  }
  // dx/dH = L/EA + int V^2/T^3 ds. The closed form (f(V_B/H) - f(V_A/H))/W0 with
  // f(v) = asinh v - v/sqrt(1+v^2) cancels for nearly straight, nearly horizontal cables:
  // there the integrand is smooth and 12-point Gauss-Legendre is exact to rounding.
  double dx_dh;
  if (std::max(std::abs(V_A), std::abs(V_B)) < 0.3 * H) {
    static constexpr std::array<double, 6> nodes = {0.1252334085114689, 0.3678314989981802,
                                                    0.5873179542866175, 0.7699026741943047,
                                                    0.9041172563704749, 0.9815606342467192};
    static constexpr std::array<double, 6> weights = {0.2491470458134028, 0.2334925365383548,
                                                      0.2031674267230659, 0.1600783285433462,
                                                      0.1069393259953184, 0.0471753363865118};
    dx_dh = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      for (double sign : {-1.0, 1.0}) {
        const double s = 0.5 * L * (1.0 + sign * nodes[i]);
        const double V = V_A + W0 * s;
        const double T = std::hypot(H, V);
        dx_dh += 0.5 * L * weights[i] * V * V / (T * T * T);
      }
    }
  } else {
    const double asinh_diff = asinh_difference(H, V_A, V_B, T_A, T_B, W0 * L);
    dx_dh = (asinh_diff - (V_B / T_B - V_A / T_A)) / W0;
  }
  Eigen::Matrix2d J;
  J << dx_dh + compliance_l, cross, cross, dz_dv + compliance_l;
  return J;
}

double stretched_increment(const CableProperties& cable, double H, double V_A, double s) {
  // s + (1/EA) int T ds, with int T ds = (V T + H^2 asinh(V/H)) / (2 W0) between the ends.
  const double compliance = inverse_stiffness(cable);
  if (compliance == 0.0) return s;
  const double W0 = cable.weight_n_per_m;
  const double T_A = std::hypot(H, V_A);
  if (W0 == 0.0) return s + compliance * s * T_A;
  const double V = V_A + W0 * s;
  const double T = std::hypot(H, V);
  double integral = 0.5 * (V * T - V_A * T_A) / W0;
  if (H > 0.0) integral += 0.5 * H * H * asinh_difference(H, V_A, V, T_A, T, W0 * s) / W0;
  return s + compliance * integral;
}

}  // namespace catena::internal
