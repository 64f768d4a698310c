// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Bessel functions of order zero in modulus-phase form (DLMF 10.18), for the `airy` solver's
/// out-of-plane string (docs/explanation/methods/airy.md):
///     J0(z) = M(z) cos theta(z),   Y0(z) = M(z) sin theta(z),
/// with theta continuous and strictly increasing from -pi/2 (z -> 0) and M decreasing. The phase
/// is returned as its small offset from the large-z line, phi(z) = theta(z) - (z - pi/4), which
/// lies in (-pi/4, 0) and tends to 0 like -1/(8 z); the modulus as sqrt(z) M(z), which tends to
/// sqrt(2/pi). Neither overflows nor loses digits for any z >= 0, including z = +inf (a string
/// of uniform tension), so differences of phases at two nearby large arguments can be formed
/// without cancellation.

namespace catena::internal {

struct BesselZeroPhase {
  double phase_offset = 0.0;    ///< phi(z) = theta(z) - z + pi/4
  double scaled_modulus = 0.0;  ///< sqrt(z) M(z) = sqrt(z (J0^2 + Y0^2))
};

/// At and above this argument the Hankel expansion (DLMF 10.17.3) is summed, whose terms fall
/// below 1e-17 relative before they start to grow; below it J0 and Y0 come from Boost.Math.
inline constexpr double kBesselHankelThreshold = 25.0;

/// phi(z) and sqrt(z) M(z) for z >= 0 (z = +inf allowed: 0 and sqrt(2/pi)).
BesselZeroPhase bessel_zero_phase(double z);

}  // namespace catena::internal
