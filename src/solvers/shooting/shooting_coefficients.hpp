// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The static coefficients the `shooting` solver integrates along s
/// (docs/explanation/methods/shooting.md): tension, tangent and normal of the elastic catenary in
/// the closed forms of the shared statics, with the scales that make the shot dimensionless. A
/// general line (docs/explanation/physics.md, "General lines") is a list of pieces, each a
/// closed-form catenary with its own section, and a list of point attachments at piece boundaries,
/// where the internal force jumps.

#include <vector>

#include "catena/core/types.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// One piece between consecutive breaks (joints, points, the touchdown point):
/// V = V_begin + W0 (s - s_begin). A grounded piece (docs/explanation/methods/shooting.md, "Seabed
/// contact") lies straight along +x on the seabed with V = 0 (W0 = 0: the seabed carries its
/// weight), the friction tension max(tension_begin + tension_slope (s - s_begin), 0), and the
/// foundation springs per stretched length of seabed.
struct ShootingPiece {
  double s_begin = 0.0;                ///< unstretched arc length of the start [m]
  double s_end = 1.0;                  ///< unstretched arc length of the end [m]
  double V_begin = 0.0;                ///< vertical force just after the start [N]
  double W0 = 0.0;                     ///< weight per unstretched length [N/m]
  double compliance = 0.0;             ///< 1/EA [1/N], 0 when inextensible
  double m = 1.0;                      ///< tangential mass m + ma_t [kg/m]
  double M = 1.0;                      ///< normal mass m + ma [kg/m]
  bool grounded = false;               ///< resting on the seabed
  double tension_begin = 0.0;          ///< grounded: tension at the start before clipping [N]
  double tension_slope = 0.0;          ///< grounded: C_B w [N/m]
  double foundation_normal = 0.0;      ///< grounded: k_s, vertical [N/m per unstretched m]
  double foundation_tangential = 0.0;  ///< grounded: k_t, along and across [N/m per unstretched m]
  double damping_tangential = 0.0;     ///< c_t [N s/m per m] (docs/explanation/physics.md)
  double damping_normal = 0.0;         ///< c_n [N s/m per m], in plane and out of plane
  double damping_axial = 0.0;          ///< c_a [N s] (Kelvin-Voigt), 0 when inextensible
  double foundation_damping = 0.0;     ///< grounded: c_s, vertical [N s/m per m]

  /// T(s) [N] for the horizontal force H of the suspended part.
  double tension(double H, double s) const;
  /// The smallest static tension on the piece [N].
  double min_tension(double H) const;
};

/// A point attachment: its inertia in the local static directions (t the bisector of the
/// tangents on both sides, n in plane, out of plane), docs/explanation/physics.md "General lines".
struct ShootingPoint {
  double s = 0.0;                ///< unstretched arc length [m]
  Vec2 t = Vec2(1.0, 0.0);       ///< bisector of the tangents on both sides
  double mass_tangential = 0.0;  ///< P + ma_t [kg]
  double mass_normal = 0.0;      ///< P + ma_n [kg]
  double mass_outofplane = 0.0;  ///< P + ma_out [kg]
};

/// Static coefficients along the cable, in the closed forms of the shared statics.
struct ShootingCoefficients {
  double length_m = 1.0;
  double H = 0.0;           ///< horizontal force [N]
  double V_A = 0.0;         ///< vertical force at s = 0 [N]
  double W0 = 0.0;          ///< weight per unstretched length [N/m] (first piece)
  double compliance = 0.0;  ///< 1/EA [1/N], 0 when inextensible (first piece)
  double m = 1.0;           ///< tangential mass m + ma_t [kg/m] (first piece)
  double M = 1.0;           ///< normal mass m + ma [kg/m] (first piece; the mass scale)
  double t_ref = 1.0;       ///< tension scale [N]: max(T_A, T_B)
  /// Pieces from a to b (one for a uniform cable) and point attachments in order of s. Empty
  /// pieces (coefficients set by hand) mean the one piece of the fields above: see all_pieces().
  std::vector<ShootingPiece> pieces;
  std::vector<ShootingPoint> points;

  static ShootingCoefficients from_statics(const StaticSolution& statics);
  /// `pieces`, or the one piece of the uniform fields when it is empty.
  std::vector<ShootingPiece> all_pieces() const;
  /// The piece containing s (at a break: the one toward b).
  const ShootingPiece& piece_at(double s) const;
  /// V(s) [N] (just beyond a point, toward b).
  double vertical_force(double s) const;
  /// T(s) [N].
  double tension(double s) const;
  /// Unit tangent and normal at s.
  Vec2 tangent(double s) const;
  Vec2 normal(double s) const;
  /// Omega^2 = w^2 L^2 M / T_ref for omega [rad/s].
  double scaled_omega2(double omega_rad_s) const;
  /// True for a general line (several pieces or point attachments).
  bool is_line() const { return pieces.size() > 1 || !points.empty(); }
  /// True when every piece is inextensible.
  bool is_inextensible() const;
  /// True when a piece rests on the seabed.
  bool has_grounded_piece() const;
  /// True when a piece carries damping (drag, axial or the seabed dashpot).
  bool is_damped() const;
};

/// A straight (vertical, H = 0) inextensible cable: its axial direction is rigid, det Phi(L)
/// vanishes for every frequency, and the in-plane problem is the transverse string alone.
bool is_straight_inextensible(const ShootingCoefficients& k);

/// Transverse travel time int sqrt(M (1+e)/T) ds [s] (Simpson, 64 intervals per piece): pi over
/// it is the string estimate of the first frequency (point masses are not in it).
double transverse_travel_time(const ShootingCoefficients& k);

}  // namespace catena::internal
