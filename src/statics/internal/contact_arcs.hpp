// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The suspended arcs of a line in general seabed contact for a given horizontal force H
/// (docs/explanation/physics.md, "Seabed contact"): the arc from end A down to its first
/// touchdown (when A is above the seabed), the arc from the last lift-off up to end B, and between
/// them the arcs lifted off the seabed by net buoyancy (a buoy or a buoyant segment). Every arc
/// meets the seabed tangentially (V = 0) on distributed weight; arcs that would overlap merge.

#include <optional>
#include <vector>

#include "catena/models/line.hpp"

namespace catena::internal {

/// The problem's contact geometry.
struct ContactGeometry {
  const Line& line;
  /// Height of end A above the seabed [m] (0: A lies on the seabed).
  double height_a_m = 0.0;
  /// Height of end B above the seabed [m] (> 0).
  double height_b_m = 0.0;
  /// True when A lies on the seabed.
  bool anchor_on_seabed = false;
};

/// A stretch of net buoyancy: buoys and buoyant segments, merged where they touch [m].
struct BuoyantStretch {
  double s_begin_m = 0.0;
  double s_end_m = 0.0;
};

/// The buoyant stretches of `line` in order of s: each buoy (weight < 0) and each segment of
/// negative weight, merged where they meet.
std::vector<BuoyantStretch> buoyant_stretches(const Line& line);

/// One suspended arc [s_begin, s_end] (unstretched arc lengths).
struct ContactArc {
  double s_begin_m = 0.0;
  double s_end_m = 0.0;
  /// Starts at end A (its vertical force there is minus the arc's weight, so that V = 0 at its
  /// touchdown); otherwise it lifts off the seabed with V = 0.
  bool from_a = false;
  /// Ends at end B; otherwise it touches down on the seabed with V = 0.
  bool to_b = false;
};

/// The arcs at horizontal force `H` (>= 0), in order of s: the last ends at B; the first starts at
/// A when A is above the seabed or a buoyant stretch lifts the anchor. std::nullopt when there is
/// no contact at this H (the arcs from A and to B merge: the line hangs free). At H = 0 there must
/// be no buoyant stretch (the caller refuses it).
std::optional<std::vector<ContactArc>> contact_arcs(const ContactGeometry& geometry,
                                                    const std::vector<BuoyantStretch>& stretches,
                                                    double H);

}  // namespace catena::internal
