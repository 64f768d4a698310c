// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The touchdown form of the elastic catenary (Turchetto 2016, docs/reference/references.md,
/// eqs. 1.6-1.10): a mooring line hanging from its lowest point (theta = 0, where it leaves a flat
/// seabed) up to a fairlead at height `depth` above the seabed. The part beyond the lowest point
/// rests on the seabed.
///
/// With c = T_H / W0 and theta the tension angle at the fairlead:
///
///     s(theta) = c tan(theta) + (T_H/EA) (c/2) [tan(theta) sec(theta) + ln(sec(theta) +
///     tan(theta))] x(theta) = c ln(sec(theta) + tan(theta)) + c tan(theta) T_H / EA y(theta) = c
///     sec(theta) (1 + (T_H/EA) sec(theta) / 2) depth    = y(theta_max) - y(0) (1.10)
///
/// Here W0 is the weight per *unstretched* length and s(theta) the *stretched* suspended length;
/// the unstretched suspended length is c tan(theta).

#include "catena/models/cable.hpp"

namespace catena {

/// A suspended mooring line from touchdown to fairlead.
struct TouchdownLine {
  /// Horizontal tension T_H [N].
  double horizontal_tension_n = 0.0;
  /// Fairlead tension angle theta_max above the horizontal [rad].
  double fairlead_angle_rad = 0.0;
  /// Fairlead tension T_H sec(theta_max) [N].
  double fairlead_tension_n = 0.0;
  /// Unstretched suspended length c tan(theta_max) [m].
  double suspended_length_m = 0.0;
  /// Stretched suspended length s(theta_max), eq. 1.6 [m].
  double suspended_stretched_length_m = 0.0;
  /// Horizontal distance from touchdown to fairlead x(theta_max), eq. 1.7 [m].
  double horizontal_reach_m = 0.0;
  /// Fairlead height above the seabed, eq. 1.10 [m].
  double depth_m = 0.0;
};

/// From water depth [m] and horizontal tension [N] (> 0): solves eq. 1.10 for theta_max (a
/// quadratic in sec(theta)). Uses the cable's W0 and EA (EA = inf allowed).
TouchdownLine touchdown_from_depth_and_tension(const CableProperties& cable,
                                               double depth_m,
                                               double horizontal_tension_n);

/// The inverse: from water depth and horizontal reach [m], finds T_H by a bracketed 1-D root of
/// x(theta_max(T_H)) = reach. Throws InvalidInput when reach <= 0 or the data are not finite.
TouchdownLine touchdown_from_depth_and_reach(const CableProperties& cable,
                                             double depth_m,
                                             double reach_m);

}  // namespace catena
