// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Parts of a general line between two arc lengths, and the weight they carry: the suspended arcs
/// of a line in general seabed contact (docs/explanation/physics.md, "Seabed contact") are built as
/// general lines of their own.

#include <cstddef>

#include "catena/models/line.hpp"

namespace catena::internal {

/// A point within this distance of a cut acts at the cut (as in build_line_pieces) [m].
inline double merge_distance(const Line& line) { return 1e-12 * line.length_m(); }

/// The part of `line` on [s_begin_m, s_end_m] (0 <= s_begin < s_end <= L), re-based to start at 0:
/// the segments clipped to it and the points strictly inside it (a point within merge_distance of
/// either cut is left out: at a touchdown or a lift-off it rests on the seabed).
/// `first_segment` receives the index in line.segments of the part's first segment.
Line line_between(const Line& line, double s_begin_m, double s_end_m, std::size_t& first_segment);

/// Weight of `line` between s_begin_m and s_end_m [N]: the segments' weight per length times the
/// length of each inside it plus the points strictly inside it (the rule of line_between).
double weight_between(const Line& line, double s_begin_m, double s_end_m);

/// Sum of |weights| of the line's segments and points [N] (0 when weightless): the force scale of
/// the statics.
double weight_scale(const Line& line);

}  // namespace catena::internal
