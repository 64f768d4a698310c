// SPDX-License-Identifier: MIT
// Parts of a general line: see line_parts.hpp.
#include "statics/internal/line_parts.hpp"

#include <algorithm>
#include <cmath>

namespace catena::internal {

Line line_between(const Line& line, double s_begin_m, double s_end_m, std::size_t& first_segment) {
  const double merge = merge_distance(line);
  Line part;
  first_segment = line.segments.size();
  double start = 0.0;
  for (std::size_t k = 0; k < line.segments.size(); ++k) {
    const double end = start + line.segments[k].length_m;
    const double begin_k = std::max(start, s_begin_m);
    const double end_k = std::min(end, s_end_m);
    start = end;
    if (!(end_k > begin_k)) continue;
    if (part.segments.empty()) first_segment = k;
    LineSegment segment = line.segments[k];
    segment.length_m = end_k - begin_k;
    part.segments.push_back(segment);
  }
  for (const PointAttachment& point : line.points) {
    if (point.s_m <= s_begin_m + merge || point.s_m >= s_end_m - merge) continue;
    PointAttachment shifted = point;
    shifted.s_m -= s_begin_m;
    part.points.push_back(shifted);
  }
  return part;
}

double weight_between(const Line& line, double s_begin_m, double s_end_m) {
  const double merge = merge_distance(line);
  double weight = 0.0;
  double start = 0.0;
  for (const LineSegment& segment : line.segments) {
    const double end = start + segment.length_m;
    const double overlap = std::min(end, s_end_m) - std::max(start, s_begin_m);
    if (overlap > 0.0) weight += segment.weight_n_per_m * overlap;
    start = end;
  }
  for (const PointAttachment& point : line.points) {
    if (point.s_m > s_begin_m + merge && point.s_m < s_end_m - merge) weight += point.weight_n;
  }
  return weight;
}

double weight_scale(const Line& line) {
  double scale = 0.0;
  for (const LineSegment& segment : line.segments)
    scale += std::abs(segment.weight_n_per_m) * segment.length_m;
  for (const PointAttachment& point : line.points) scale += std::abs(point.weight_n);
  return scale;
}

}  // namespace catena::internal
