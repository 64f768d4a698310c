// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Statics of a line over a flat seabed (docs/explanation/physics.md, "Seabed contact"): where the
/// hanging line would go below the seabed it rests on it, straight and horizontal, in any number
/// of grounded stretches; the suspended arcs between them meet the seabed tangentially (V = 0).
/// Either end may be above the seabed (U and W shapes, shared lines); a slack line (H = 0) hangs
/// vertically to the seabed and lies on it with zero tension.

#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena {

/// Solves the statics of `problem` with its seabed (without one: solve_statics).
///
/// First the line is solved without the seabed; when that solution converges, stays on or above
/// the seabed and (with A on the seabed) leaves A upward (V_A >= 0), it is the answer (no contact,
/// bit for bit the solution without a seabed). Otherwise:
/// - end A on the seabed and no buoyancy (no buoy, no segment of negative weight): one grounded
///   stretch from A with Coulomb friction; for each H the grounded length L_g is found by
///   bisection so that the suspended part reaches the fairlead's height, H by bisection so that it
///   reaches its horizontal position (each to adjacent doubles);
/// - otherwise general contact (src/statics/internal/general_contact.hpp): the arc from A down to
///   its first touchdown (A above the seabed), the arcs lifted off the seabed by buoyancy (zero net
///   weight, V = 0 and z = seabed at both ends), the arc from the last lift-off up to B, merged
///   where they overlap; grounded stretches between them at tension H (friction only on the
///   stretch from an anchor lying on the seabed); H by bisection on the horizontal reach.
/// When even H -> 0 reaches past B the line is slack: H = 0, vertical hanging parts, zero tension
/// on the seabed, and the grounded length that does not fit in the span in a heap at the foot of
/// the part hanging from B (StaticSolution::slack_length_m).
///
/// Bad input throws InvalidInput: an invalid problem (seabed.* fields, an end below the seabed),
/// end B on the seabed (a line entirely on the seabed, or with A above it: mirror the line), and
/// the cases outside the model, each saying "not supported": a weightless segment on the
/// seabed, a slack line with buoyancy, a touchdown or lift-off at a point weight (the line would
/// meet the seabed at an angle), a configuration whose suspended parts would pass below the seabed,
/// and a line that reaches B at no horizontal force. A bisection that does not close the chord is
/// returned with `converged == false` and the reason.
StaticSolution solve_seabed_statics(const Problem& problem, const StaticsOptions& options = {});

}  // namespace catena
