// SPDX-License-Identifier: MIT
#include "catena/statics/touchdown_catenary.hpp"

#include <fmt/format.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>

#include "catena/core/error.hpp"

namespace catena {
namespace {

void require_positive(double value, const char* name, const char* unit) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(
        fmt::format("Invalid touchdown {} = {}: must be finite and > 0 [{}]", name, value, unit));
  }
}

}  // namespace

TouchdownLine touchdown_from_depth_and_tension(const CableProperties& cable,
                                               double depth_m,
                                               double horizontal_tension_n) {
  cable.validate();
  require_positive(depth_m, "depth_m", "m");
  require_positive(horizontal_tension_n, "horizontal_tension_n", "N");
  const double T_H = horizontal_tension_n;
  const double c = T_H / cable.weight_n_per_m;  // (1.9)
  const double k = cable.is_inextensible() ? 0.0 : T_H / cable.axial_stiffness_n;
  // (1.10) as a quadratic in S = sec(theta): (c k/2) S^2 + c S - Q = 0, Q = depth + c (1 + k/2).
  // The root in the form 2Q / (c + sqrt(c^2 + 2 c k Q)) does not cancel as k -> 0.
  const double Q = depth_m + c * (1.0 + 0.5 * k);
  const double sec = 2.0 * Q / (c + std::sqrt(c * c + 2.0 * c * k * Q));
  const double tan = std::sqrt((sec - 1.0) * (sec + 1.0));
  const double log_term = std::log(sec + tan);

  TouchdownLine line;
  line.horizontal_tension_n = T_H;
  line.fairlead_angle_rad = std::atan(tan);
  line.fairlead_tension_n = T_H * sec;
  line.suspended_length_m = c * tan;
  line.suspended_stretched_length_m = c * tan + 0.5 * k * c * (tan * sec + log_term);  // (1.6)
  line.horizontal_reach_m = c * log_term + c * tan * k;                                // (1.7)
  line.depth_m = c * sec * (1.0 + 0.5 * k * sec) - c * (1.0 + 0.5 * k);                // (1.10)
  return line;
}

TouchdownLine touchdown_from_depth_and_reach(const CableProperties& cable,
                                             double depth_m,
                                             double reach_m) {
  cable.validate();
  require_positive(depth_m, "depth_m", "m");
  require_positive(reach_m, "reach_m", "m");
  // The reach grows monotonically with T_H (from 0 as T_H -> 0 to infinity): bracket in T_H by
  // doubling from a scale of W0 * depth, then TOMS 748.
  auto excess = [&](double T_H) {
    return touchdown_from_depth_and_tension(cable, depth_m, T_H).horizontal_reach_m - reach_m;
  };
  double low = cable.weight_n_per_m * depth_m * 1e-3;
  double high = cable.weight_n_per_m * std::max(depth_m, reach_m);
  for (int i = 0; i < 200 && excess(low) > 0.0; ++i) low *= 0.5;
  for (int i = 0; i < 200 && excess(high) < 0.0; ++i) high *= 2.0;
  if (!(excess(low) <= 0.0 && excess(high) >= 0.0)) {
    throw InvalidInput(fmt::format(
        "Touchdown: no horizontal tension gives reach {} m at depth {} m", reach_m, depth_m));
  }
  boost::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      excess, low, high, boost::math::tools::eps_tolerance<double>(52), iterations);
  return touchdown_from_depth_and_tension(cable, depth_m, 0.5 * (bracket.first + bracket.second));
}

}  // namespace catena
