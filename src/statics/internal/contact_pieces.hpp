// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The pieces of a line in general seabed contact (docs/explanation/physics.md, "Seabed
/// contact"), given its suspended arcs at a horizontal force H: the arcs as general-line pieces,
/// the stretches between them grounded (tension H, or the friction law on the stretch from an
/// anchor lying on the seabed), and on a slack line (H = 0) the heap of the grounded length that
/// does not fit in the span.

#include <vector>

#include "catena/statics/elastic_catenary.hpp"
#include "statics/internal/contact_arcs.hpp"

namespace catena::internal {

struct ContactPieces {
  std::vector<StaticPiece> pieces;
  /// Largest height above (or below) the seabed at which an arc that should touch down ends [m]:
  /// the part of the closure the horizontal solve does not see.
  double touchdown_miss_m = 0.0;
};

/// Pieces (offsets relative to A) of `geometry.line` with the `arcs` of contact_arcs at `H`, on
/// a seabed `seabed_offset_z_m` above A (<= 0), friction `friction` on the stretch from an anchor
/// lying on the seabed. `heap_length_m` (> 0 only at H = 0) of the grounded stretch before the arc
/// into B lies in a heap at the foot of that arc (StaticPiece::slack_heap).
ContactPieces build_contact_pieces(const ContactGeometry& geometry,
                                   double friction,
                                   double seabed_offset_z_m,
                                   double H,
                                   const std::vector<ContactArc>& arcs,
                                   double heap_length_m);

}  // namespace catena::internal
