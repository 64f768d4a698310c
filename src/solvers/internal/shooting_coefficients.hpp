#pragma once
/// \file
/// The static coefficients the `shooting` solver integrates along s (docs/methods/shooting.md):
/// tension, tangent and normal of the elastic catenary in the closed forms of the shared statics,
/// with the scales that make the shot dimensionless.

#include "catena/core/types.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// Static coefficients along the cable, in the closed forms of the shared statics.
struct ShootingCoefficients {
  double length_m = 1.0;
  double H = 0.0;           ///< horizontal force [N]
  double V_A = 0.0;         ///< vertical force at s = 0 [N]
  double W0 = 0.0;          ///< weight per unstretched length [N/m]
  double compliance = 0.0;  ///< 1/EA [1/N], 0 when inextensible
  double m = 1.0;           ///< mass [kg/m] (tangential inertia)
  double M = 1.0;           ///< normal mass m + ma [kg/m]
  double t_ref = 1.0;       ///< tension scale [N]: max(T_A, T_B)

  static ShootingCoefficients from_statics(const StaticSolution& statics);
  /// T(s) [N].
  double tension(double s) const;
  /// Unit tangent and normal at s.
  Vec2 tangent(double s) const;
  Vec2 normal(double s) const;
  /// Omega^2 = w^2 L^2 M / T_ref for omega [rad/s].
  double scaled_omega2(double omega_rad_s) const;
};

/// A straight (vertical, H = 0) inextensible cable: its axial direction is rigid, det Phi(L)
/// vanishes for every frequency, and the in-plane problem is the transverse string alone.
bool is_straight_inextensible(const ShootingCoefficients& k);

/// Transverse travel time int sqrt(M (1+e)/T) ds [s] (Simpson, 64 intervals): pi over it is the
/// string estimate of the first frequency.
double transverse_travel_time(const ShootingCoefficients& k);

}  // namespace catena::internal
