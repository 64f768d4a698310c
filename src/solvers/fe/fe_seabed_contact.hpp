// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Where `fe`'s linear dynamics on the seabed is singular (docs/explanation/methods/fe.md, "Seabed
/// contact"): a grounded stretch left without static tension by the seabed friction resists
/// transverse motion only through the foundation, so a plane whose foundation stiffness is zero
/// there has a continuum of zero frequencies. Such a plane is declined with what to change.

#include <optional>
#include <string>

#include "catena/core/types.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// Unstretched length of the grounded stretch with zero static tension [m] (0 without contact).
double slack_grounded_length_m(const StaticSolution& statics);

/// Why `plane` has no well-posed dynamics on this seabed contact (a slack grounded stretch and no
/// foundation stiffness across it: k_t out of plane, k_s in plane); nullopt when it has.
std::optional<std::string> seabed_plane_singular(Plane plane, const StaticSolution& statics);

/// Why fe declines a slack line (H = 0 on the seabed: the hanging part leaves the seabed with zero
/// tension), or nullopt. There the continuous modes of the hanging part and of the grounded
/// stretch do not meet (zero tension transmits no transverse force, so the hanging chain's foot
/// moves freely, J0(2 omega sqrt(l M / w)) = 0), while the chain's lift-off node carries the
/// grounded stretch's foundation share and is held by it: the frequencies converge only
/// logarithmically in the mesh size (measured on a 50 m hanging chain with k = 1e5 N/m/m: 28 %,
/// 25 %, 22 %, 19 % from the Bessel frequency at N = 100 ... 800), far below the order fe's
/// estimate assumes.
std::optional<std::string> slack_line_declined(const StaticSolution& statics);

}  // namespace catena::internal
