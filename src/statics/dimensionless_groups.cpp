// SPDX-License-Identifier: MIT
#include "catena/statics/dimensionless_groups.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "catena/core/error.hpp"
#include "catena/statics/gale_coordinates.hpp"

namespace catena {

double DimensionlessGroups::k_l_over_pi(double omega_rad_s) const {
  return omega_rad_s / taut_frequency_scale_rad_s / kPi;
}

double DimensionlessGroups::omega_from_k_l_over_pi(double value) const {
  return value * kPi * taut_frequency_scale_rad_s;
}

std::optional<double> DimensionlessGroups::gale_ratio(double omega_rad_s) const {
  if (!(gale_frequency_scale_rad_s > 0.0)) return std::nullopt;
  return omega_rad_s / gale_frequency_scale_rad_s;
}

double DimensionlessGroups::omega_from_gale_ratio(double ratio) const {
  if (!(gale_frequency_scale_rad_s > 0.0)) {
    throw InvalidInput(
        "Gale's frequency ratio w/sqrt(g/a) is undefined for a vertical cable (H = 0, a = 0)");
  }
  return ratio * gale_frequency_scale_rad_s;
}

namespace {

// A general line: only the groups that keep a meaning (see DimensionlessGroups::uniform).
DimensionlessGroups line_groups(const Problem& problem, const StaticSolution& statics) {
  const Line& line = problem.line;
  const double L = line.length_m();
  double mass = 0.0;
  double normal_mass = 0.0;
  for (const LineSegment& segment : line.segments) {
    mass += segment.mass_kg_per_m * segment.length_m;
    normal_mass += segment.normal_mass_kg_per_m() * segment.length_m;
  }
  const Vec2 chord = problem.supports.chord_m();
  DimensionlessGroups g;
  g.uniform = false;
  g.chord_angle_rad = std::atan2(chord.y(), chord.x());
  g.t0_n = std::max(statics.tension_n(0.0), statics.tension_n(L));
  g.mass_ratio = mass / normal_mass;
  g.taut_frequency_scale_rad_s = std::sqrt(g.t0_n / (normal_mass / L)) / L;
  return g;
}

}  // namespace

DimensionlessGroups compute_dimensionless_groups(const Problem& problem,
                                                 const StaticSolution& statics) {
  if (!problem.is_uniform()) return line_groups(problem, statics);
  const CableProperties& cable = problem.cable;
  const double L = cable.length_m;
  const double W0 = cable.weight_n_per_m;
  const double H = statics.horizontal_force_n();
  const double V_A = statics.vertical_force_a_n();
  const double V_B = statics.vertical_force_n(L);
  const Vec2 chord = problem.supports.chord_m();

  DimensionlessGroups g;
  g.chord_angle_rad = std::atan2(chord.y(), chord.x());
  if (H > 0.0) {
    // The static angle equals phi_a where V(s_a) = H tan(phi_a) = H dz/dx.
    const double V_a = H * chord.y() / chord.x();
    g.s_at_chord_angle_m = (V_a - V_A) / W0;
    g.t0_n = std::hypot(H, V_a);
  } else {
    // Vertical limit (H -> 0): cot(angle) = H/V(s) equals dx/dz = H int (1+e)/|V| / int (1+e),
    // so |V(s_a)| = int (1+e) ds / int (1+e)/|V| ds (a harmonic mean of the tension).
    const double compliance = cable.is_inextensible() ? 0.0 : 1.0 / cable.axial_stiffness_n;
    const double stretched = L + compliance * std::abs(V_A * L + 0.5 * W0 * L * L);
    const double inverse_integral = std::abs(std::log(V_B / V_A)) / W0 + compliance * L;
    const double V_abs = stretched / inverse_integral;
    g.t0_n = V_abs;
    g.s_at_chord_angle_m = (std::copysign(V_abs, V_A) - V_A) / W0;
  }
  g.eps = W0 * L / g.t0_n;
  const double cos_phi = std::cos(g.chord_angle_rad);
  g.lambda2 = cable.is_inextensible()
                  ? kInfinity
                  : cable.axial_stiffness_n * g.eps * g.eps * cos_phi * cos_phi / g.t0_n;
  g.mass_ratio = cable.mass_kg_per_m / cable.normal_mass_kg_per_m();
  g.taut_frequency_scale_rad_s = std::sqrt(g.t0_n / cable.normal_mass_kg_per_m()) / L;

  if (H > 0.0) {
    g.has_apex_parameterization = true;
    g.catenary_parameter_m = H / W0;
    g.sigma1 = V_A / H;
    g.sigma2 = V_B / H;
    g.xi1 = gale_xi_from_sigma(g.sigma1);
    g.xi2 = gale_xi_from_sigma(g.sigma2);
    // sqrt(g/a) with g = W0/m and a = H/W0.
    g.gale_frequency_scale_rad_s = W0 / std::sqrt(cable.mass_kg_per_m * H);
    g.height_over_span = chord.y() / chord.x();
    if (L > std::abs(chord.y())) {
      g.sag_parameter = chord.x() / std::sqrt((L - chord.y()) * (L + chord.y()));
    }
  }
  return g;
}

std::string to_string(FrequencyUnit unit) {
  switch (unit) {
    case FrequencyUnit::RadPerSecond:
      return "rad/s";
    case FrequencyUnit::Hertz:
      return "Hz";
    case FrequencyUnit::KLOverPi:
      return "kL/pi";
    case FrequencyUnit::GaleRatio:
      return "gale";
  }
  return "?";
}

std::optional<FrequencyUnit> parse_frequency_unit(const std::string& text) {
  if (text == "rad/s") return FrequencyUnit::RadPerSecond;
  if (text == "Hz" || text == "hz") return FrequencyUnit::Hertz;
  if (text == "kL/pi") return FrequencyUnit::KLOverPi;
  if (text == "gale") return FrequencyUnit::GaleRatio;
  return std::nullopt;
}

double to_rad_per_second(double value, FrequencyUnit unit, const DimensionlessGroups& groups) {
  switch (unit) {
    case FrequencyUnit::RadPerSecond:
      return value;
    case FrequencyUnit::Hertz:
      return 2.0 * kPi * value;
    case FrequencyUnit::KLOverPi:
      return groups.omega_from_k_l_over_pi(value);
    case FrequencyUnit::GaleRatio:
      return groups.omega_from_gale_ratio(value);
  }
  return value;
}

double from_rad_per_second(double omega_rad_s,
                           FrequencyUnit unit,
                           const DimensionlessGroups& groups) {
  switch (unit) {
    case FrequencyUnit::RadPerSecond:
      return omega_rad_s;
    case FrequencyUnit::Hertz:
      return omega_rad_s / (2.0 * kPi);
    case FrequencyUnit::KLOverPi:
      return groups.k_l_over_pi(omega_rad_s);
    case FrequencyUnit::GaleRatio: {
      const auto ratio = groups.gale_ratio(omega_rad_s);
      if (!ratio) throw InvalidInput("Gale's frequency ratio is undefined for a vertical cable");
      return *ratio;
    }
  }
  return omega_rad_s;
}

}  // namespace catena
