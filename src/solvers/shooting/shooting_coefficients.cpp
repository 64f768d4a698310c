// SPDX-License-Identifier: MIT
// Static coefficients of the shooting solver: see shooting_coefficients.hpp.
#include "solvers/shooting/shooting_coefficients.hpp"

#include <algorithm>
#include <cmath>

namespace catena::internal {

namespace {

ShootingPiece piece_of(const CableProperties& section, double s_begin, double V_begin) {
  ShootingPiece p;
  p.s_begin = s_begin;
  p.s_end = s_begin + section.length_m;
  p.V_begin = V_begin;
  p.W0 = section.weight_n_per_m;
  p.compliance = section.is_inextensible() ? 0.0 : 1.0 / section.axial_stiffness_n;
  // The tangential inertia: the mass and the tangential added mass (0 unless given, so that a
  // line without it is unchanged to the bit).
  p.m = section.tangential_mass_kg_per_m();
  p.M = section.normal_mass_kg_per_m();
  p.damping_tangential = section.damping.tangential_n_s_per_m2;
  p.damping_normal = section.damping.normal_n_s_per_m2;
  p.damping_axial = section.damping.axial_n_s;
  return p;
}

// A point's inertia in its local frame: t bisects the static tangents on both sides.
ShootingPoint point_of(const PointAttachment& attachment, const StaticSolution& statics) {
  ShootingPoint p;
  p.s = attachment.s_m;
  const double H = statics.horizontal_force_n();
  const Vec2 before = Vec2(H, statics.vertical_force_before_n(p.s)).normalized();
  const Vec2 after = Vec2(H, statics.vertical_force_n(p.s)).normalized();
  p.t = (before + after).normalized();
  p.mass_tangential = attachment.mass_kg + attachment.tangential_added_mass_kg();
  p.mass_normal = attachment.mass_kg + attachment.normal_added_mass_kg();
  p.mass_outofplane = attachment.mass_kg + attachment.outofplane_added_mass_kg();
  return p;
}

// A grounded piece of the seabed statics: V = 0, the friction tension, the foundation springs.
ShootingPiece grounded_piece_of(const StaticPiece& piece, const Seabed& seabed) {
  ShootingPiece p = piece_of(piece.section, piece.s_begin_m, 0.0);
  p.grounded = true;
  p.W0 = 0.0;
  p.tension_begin = piece.grounded_tension_begin_n;
  p.tension_slope = piece.grounded_tension_slope_n_per_m;
  p.foundation_normal = seabed.stiffness_n_per_m2;
  p.foundation_tangential = seabed.tangential_stiffness_n_per_m2;
  p.foundation_damping = seabed.damping_n_s_per_m2;
  return p;
}

}  // namespace

double ShootingPiece::tension(double H, double s) const {
  if (grounded) return std::max(tension_begin + tension_slope * (s - s_begin), 0.0);
  return std::hypot(H, V_begin + W0 * (s - s_begin));
}

double ShootingPiece::min_tension(double H) const {
  // Monotone on a piece (|V| linear, or the friction profile): the extremes are at the ends.
  return std::min(tension(H, s_begin), tension(H, s_end));
}

ShootingCoefficients ShootingCoefficients::from_statics(const StaticSolution& statics) {
  const CableProperties& cable = statics.cable();
  ShootingCoefficients c;
  c.length_m = cable.length_m;
  c.H = statics.horizontal_force_n();
  c.V_A = statics.vertical_force_a_n();
  if (statics.is_line()) {
    const Line line = statics.line();  // by value: a reference into statics.line() would dangle
    for (const StaticPiece& piece : statics.pieces()) {
      // A line entirely on the seabed ends in an empty suspended piece: nothing to integrate.
      if (statics.has_contact() && !piece.grounded && piece.section.length_m <= 0.0) continue;
      c.pieces.push_back(piece.grounded
                             ? grounded_piece_of(piece, statics.seabed())
                             : piece_of(piece.section, piece.s_begin_m, piece.vertical_begin_n));
      // The statics' sections carry no damping (it does not enter the statics): the segment's.
      const SectionDamping& damping = line.segments[piece.segment].damping;
      c.pieces.back().damping_tangential = damping.tangential_n_s_per_m2;
      c.pieces.back().damping_normal = damping.normal_n_s_per_m2;
      c.pieces.back().damping_axial = damping.axial_n_s;
    }
    c.pieces.back().s_end = cable.length_m;
    for (const PointAttachment& point : line.points) {
      c.points.push_back(point_of(point, statics));
    }
  } else {
    c.pieces.push_back(piece_of(cable, 0.0, c.V_A));
  }
  const ShootingPiece& first = c.pieces.front();
  c.W0 = first.W0;
  c.compliance = first.compliance;
  c.m = first.m;
  c.M = first.M;
  c.t_ref = std::max(statics.tension_n(0.0), statics.tension_n(cable.length_m));
  return c;
}

std::vector<ShootingPiece> ShootingCoefficients::all_pieces() const {
  if (!pieces.empty()) return pieces;
  ShootingPiece p;
  p.s_end = length_m;
  p.V_begin = V_A;
  p.W0 = W0;
  p.compliance = compliance;
  p.m = m;
  p.M = M;
  return {p};
}

const ShootingPiece& ShootingCoefficients::piece_at(double s) const {
  std::size_t j = 0;
  while (j + 1 < pieces.size() && s >= pieces[j + 1].s_begin) ++j;
  return pieces[j];
}

double ShootingCoefficients::vertical_force(double s) const {
  if (pieces.empty()) return V_A + W0 * s;
  const ShootingPiece& p = piece_at(s);
  return p.V_begin + p.W0 * (s - p.s_begin);
}

double ShootingCoefficients::tension(double s) const {
  if (pieces.empty()) return std::hypot(H, vertical_force(s));
  return piece_at(s).tension(H, s);
}

Vec2 ShootingCoefficients::tangent(double s) const {
  const double V = vertical_force(s);
  const double T = std::hypot(H, V);
  return Vec2(H / T, V / T);
}

Vec2 ShootingCoefficients::normal(double s) const {
  const double V = vertical_force(s);
  const double T = std::hypot(H, V);
  return Vec2(-V / T, H / T);
}

double ShootingCoefficients::scaled_omega2(double omega_rad_s) const {
  return omega_rad_s * omega_rad_s * length_m * length_m * M / t_ref;
}

bool ShootingCoefficients::is_inextensible() const {
  if (pieces.empty()) return compliance == 0.0;
  return std::all_of(pieces.begin(), pieces.end(),
                     [](const ShootingPiece& p) { return p.compliance == 0.0; });
}

bool ShootingCoefficients::has_grounded_piece() const {
  return std::any_of(pieces.begin(), pieces.end(),
                     [](const ShootingPiece& p) { return p.grounded; });
}

bool ShootingCoefficients::is_damped() const {
  return std::any_of(pieces.begin(), pieces.end(), [](const ShootingPiece& p) {
    return p.damping_tangential != 0.0 || p.damping_normal != 0.0 || p.damping_axial != 0.0 ||
           p.foundation_damping != 0.0;
  });
}

bool is_straight_inextensible(const ShootingCoefficients& k) {
  return k.H == 0.0 && k.is_inextensible();
}

double transverse_travel_time(const ShootingCoefficients& k) {
  constexpr int kIntervals = 64;
  double total = 0.0;
  for (const ShootingPiece& piece : k.all_pieces()) {
    const double h = (piece.s_end - piece.s_begin) / kIntervals;
    double sum = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
      const double s = piece.s_begin + i * h;
      const double T = piece.tension(k.H, s);
      const double value = std::sqrt(piece.M * (1.0 + T * piece.compliance) / T);
      const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      sum += weight * value;
    }
    total += sum * h / 3.0;
  }
  return total;
}

}  // namespace catena::internal
