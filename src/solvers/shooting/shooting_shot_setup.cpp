// SPDX-License-Identifier: MIT
// Breaks and axial frame of a shot: see shooting_shot_setup.hpp.
#include "solvers/shooting/shooting_shot_setup.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "solvers/shooting/shooting_integrator.hpp"

namespace catena::internal {

// The breaks of the line in the order of integration (none for a uniform cable).
std::vector<Break> breaks_of(const ShootingCoefficients& k, bool from_b) {
  std::vector<Break> breaks;
  const std::size_t n = k.pieces.size();
  for (std::size_t j = 1; j < n; ++j) {
    const std::size_t piece = from_b ? n - j : j;
    const double s = k.pieces[piece].s_begin;
    Break b;
    b.x = from_b ? 1.0 - s / k.length_m : s / k.length_m;
    b.next_piece = from_b ? piece - 1 : piece;
    for (std::size_t p = 0; p < k.points.size(); ++p) {
      if (std::abs(k.points[p].s - s) <= 1e-10 * k.length_m) b.point = static_cast<int>(p);
    }
    breaks.push_back(b);
  }
  return breaks;
}

// The extreme tangent angles over the pieces [rad]: the tangent angle is monotone on each piece,
// so its extremes are at the piece ends.
static std::pair<double, double> tangent_angle_range(const ShootingCoefficients& k) {
  double theta_a = std::atan2(k.V_A, k.H);
  double theta_b = std::atan2(k.vertical_force(k.length_m), k.H);
  for (const ShootingPiece& p : k.pieces) {
    const double ends[2] = {std::atan2(p.V_begin, k.H),
                            std::atan2(p.V_begin + p.W0 * (p.s_end - p.s_begin), k.H)};
    for (double theta : ends) {
      theta_a = std::min(theta_a, theta);
      theta_b = std::max(theta_b, theta);
    }
  }
  return {theta_a, theta_b};
}

double tangent_turn_rad(const ShootingCoefficients& k) {
  const auto [theta_a, theta_b] = tangent_angle_range(k);
  return std::abs(theta_b - theta_a);
}

// The axial frame of the header: a constant rotation to the mean tangent (the bisector of the
// end tangents) and the axial stretch sigma.
void set_axial_frame(const ShootingCoefficients& k, RhsData& data) {
  const auto [theta_a, theta_b] = tangent_angle_range(k);
  double max_compliance = 0.0;
  for (const ShootingPiece& p : k.pieces) max_compliance = std::max(max_compliance, p.compliance);
  const double theta_c = 0.5 * (theta_a + theta_b);
  const double sigma = axial_stretch(k.t_ref * max_compliance, 0.5 * std::abs(theta_b - theta_a));
  // A cable whose axial component is within kMinAxialStretch of the normal one keeps its digits in
  // x and y: it is shot as before, in the physical frame (data's identity default).
  if (sigma < kMinAxialStretch) return;
  Eigen::Matrix2d rotation_t;  // R^T, R = [t_c n_c]
  rotation_t << std::cos(theta_c), std::sin(theta_c), -std::sin(theta_c), std::cos(theta_c);
  data.to_axial = Eigen::Vector2d(sigma, 1.0).asDiagonal() * rotation_t;
  data.to_axial_force = Eigen::Vector2d(1.0 / sigma, 1.0).asDiagonal() * rotation_t;
}

// The normal compliance of the carried system is B_n = T_ref (1 + e) / T, about 1 for a small
// static strain but ~T_ref / EA once the strain exceeds 1: balancing as if B_n were 1 left the
// carried Phi ~1e5 times larger than F at T0/EA = 7.5e5 (taut_inclined eps = 0.1, lambda^2 =
// 1e-8), the phase turned in bursts the stepper stepped over, the conjugate-point count went wrong
// and shooting returned a false double root 0.35 % off (49 % at lambda^2 = 1e-9, a rejected count
// at 1e-10). Balancing with b = max(1, T_ref / EA) (the strain at the reference tension, the
// largest) keeps the phase rate sqrt(B C) uniform; b = 1 below a strain of 1 keeps the shots of
// every ordinary cable bit for bit what they were.
void set_balance(const ShootingCoefficients& k, double omega_scaled, bool balance, RhsData& data) {
  data.kappa2 = 1.0;
  data.balance_moves = false;
  if (!balance) return;
  double max_compliance = k.compliance;
  for (const ShootingPiece& p : k.pieces) max_compliance = std::max(max_compliance, p.compliance);
  const double b = std::max(1.0, k.t_ref * max_compliance);
  const double rate = omega_scaled * std::sqrt(b);
  data.kappa2 = std::max(rate, 1.0) / b;
  data.balance_moves = rate > 1.0;
}

}  // namespace catena::internal
