// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Statics of a line over a flat seabed (docs/explanation/physics.md, "Seabed contact"): end A (the
/// anchor) lies on the seabed; where the hanging line would go below it, a grounded length L_g from
/// A rests on it, straight and horizontal, with Coulomb friction; the rest is suspended and leaves
/// the seabed tangentially (V = 0 at the touchdown point).

#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

/// Solves the statics of `problem` with its seabed (without one: solve_statics).
///
/// First the line is solved without the seabed; when that solution converges with V_A >= 0 and
/// stays on or above the seabed, it is the answer (no contact, L_g = 0, bit for bit the solution
/// without a seabed). Otherwise the contact equations are solved for (H, L_g): for each H, L_g
/// is found by bisection so that the suspended part from the touchdown point reaches the
/// fairlead's height; H by bisection so that it also reaches the fairlead's horizontal position
/// (each bisection to adjacent doubles; both functions are monotone for a line of positive weight).
///
/// Bad input throws InvalidInput: an invalid problem (seabed.* fields, end A off the seabed, end B
/// below it), a fairlead on the seabed (a line entirely on the seabed), a line so long that even
/// hanging vertically its grounded part would pass the fairlead (no equilibrium: it would fold on
/// the seabed), and the cases outside the model, each saying "not supported": a buoy or a
/// buoyant or weightless segment on the grounded part, and a suspended part that goes below the
/// seabed again (lift-off of a buoyant segment and a second contact interval). A bisection that
/// does not close the chord is returned with `converged == false` and the reason.
StaticSolution solve_seabed_statics(const Problem& problem, const StaticsOptions& options = {});

}  // namespace catena
