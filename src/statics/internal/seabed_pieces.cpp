// SPDX-License-Identifier: MIT
// Pieces of a line resting partly on the seabed: see seabed_pieces.hpp.
#include "statics/internal/seabed_pieces.hpp"

#include <algorithm>
#include <cmath>

#include "statics/internal/catenary_segment.hpp"
#include "statics/internal/line_pieces.hpp"

namespace catena::internal {
namespace {

// A point within `merge` of a cut acts at the cut (as in build_line_pieces).
double merge_distance(const Line& line) { return 1e-12 * line.length_m(); }

// Weight resting on the seabed beyond s up to the touchdown point: the segments' weight over
// (s, L_g) plus the points in (s, L_g] [N]. A point at s itself is on the side of A.
double grounded_weight_beyond(const Line& line, double s, double grounded_length) {
  const double merge = merge_distance(line);
  double weight = 0.0;
  for (std::size_t k = 0; k < line.segments.size(); ++k) {
    const double begin = std::max(line.segment_start_m(k), s);
    const double end = std::min(line.segment_start_m(k + 1), grounded_length);
    if (end > begin) weight += line.segments[k].weight_n_per_m * (end - begin);
  }
  for (const PointAttachment& point : line.points) {
    if (point.s_m > s + merge && point.s_m <= grounded_length + merge) weight += point.weight_n;
  }
  return weight;
}

// Where the friction tension H - C_B W(s) reaches 0 (it grows with s), found by bisection to
// adjacent doubles; -1 when it stays positive down to A.
double slack_end(const Line& line, double friction, double H, double grounded_length) {
  auto tension = [&](double s) {
    return H - friction * grounded_weight_beyond(line, s, grounded_length);
  };
  if (friction == 0.0 || tension(0.0) >= 0.0) return -1.0;
  double lo = 0.0;
  double hi = grounded_length;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (tension(mid) < 0.0 ? lo : hi) = mid;
  }
  return hi;
}

// Cuts of the grounded part: A, the joints and points before L_g, the slack end, L_g.
std::vector<double> grounded_cuts(const Line& line, double slack, double grounded_length) {
  const double merge = merge_distance(line);
  std::vector<double> cuts{0.0, grounded_length};
  for (std::size_t k = 1; k < line.segments.size(); ++k) cuts.push_back(line.segment_start_m(k));
  for (const PointAttachment& point : line.points) cuts.push_back(point.s_m);
  cuts.push_back(slack);
  std::vector<double> kept;
  std::sort(cuts.begin(), cuts.end());
  for (double cut : cuts) {
    if (cut < 0.0 || cut > grounded_length - merge) continue;
    if (kept.empty() || cut > kept.back() + merge) kept.push_back(cut);
  }
  kept.push_back(grounded_length);
  return kept;
}

// Index of the segment containing s (at a joint: the one toward B).
std::size_t segment_index(const Line& line, double s) {
  const double merge = merge_distance(line);
  std::size_t k = 0;
  while (k + 1 < line.segments.size() && line.segment_start_m(k + 1) <= s + merge) ++k;
  return k;
}

}  // namespace

Line line_beyond(const Line& line, double s_m, std::size_t& first_segment) {
  const double merge = merge_distance(line);
  first_segment = segment_index(line, s_m);
  Line part;
  for (std::size_t k = first_segment; k < line.segments.size(); ++k) {
    LineSegment segment = line.segments[k];
    if (k == first_segment) segment.length_m = line.segment_start_m(k + 1) - s_m;
    part.segments.push_back(segment);
  }
  for (const PointAttachment& point : line.points) {
    if (point.s_m <= s_m + merge) continue;
    PointAttachment shifted = point;
    shifted.s_m -= s_m;
    part.points.push_back(shifted);
  }
  return part;
}

double grounded_tension(const StaticPiece& piece, double ds) {
  return std::max(piece.grounded_tension_begin_n + piece.grounded_tension_slope_n_per_m * ds, 0.0);
}

double grounded_stretched_increment(const StaticPiece& piece, double ds) {
  // int_0^ds max(T0 + k t, 0) dt with k = C_B w >= 0: the positive part starts at t0.
  const double T0 = piece.grounded_tension_begin_n;
  const double k = piece.grounded_tension_slope_n_per_m;
  double integral;
  if (k == 0.0) {
    integral = std::max(T0, 0.0) * ds;
  } else {
    const double t0 = std::clamp(-T0 / k, 0.0, ds);
    integral = T0 * (ds - t0) + 0.5 * k * (ds * ds - t0 * t0);
  }
  return ds + inverse_stiffness(piece.section) * std::max(integral, 0.0);
}

double append_anchor_stretch(std::vector<StaticPiece>& pieces,
                             const Line& line,
                             double friction,
                             double seabed_offset_z_m,
                             double H,
                             double grounded_length_m) {
  const double slack = slack_end(line, friction, H, grounded_length_m);
  const std::vector<double> cuts = grounded_cuts(line, slack, grounded_length_m);
  // A friction so large that the tensioned stretch before the touchdown, H / (friction w), is
  // within the merge distance of L_g: that stretch's elastic elongation (below H merge / EA) is
  // beyond rounding, and the piece's tension, H - friction W with friction W >> H, would be a
  // difference of huge numbers (issue 32: friction 1e12 failed to close). The grounded part is
  // then slack.
  const bool all_slack = slack >= grounded_length_m - merge_distance(line);
  double x = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size() && grounded_length_m > 0.0; ++i) {
    const std::size_t k = segment_index(line, cuts[i]);
    const double length = cuts[i + 1] - cuts[i];
    StaticPiece piece{section_of(line.segments[k], length), k, cuts[i], 0.0,
                      Vec2(x, seabed_offset_z_m),           x};
    piece.grounded = true;
    piece.grounded_tension_begin_n =
        all_slack ? 0.0 : H - friction * grounded_weight_beyond(line, cuts[i], grounded_length_m);
    piece.grounded_tension_slope_n_per_m =
        all_slack ? 0.0 : friction * piece.section.weight_n_per_m;
    x += grounded_stretched_increment(piece, length);
    pieces.push_back(piece);
  }
  return x;
}

std::vector<StaticPiece> build_seabed_pieces(const Line& line,
                                             double friction,
                                             double seabed_offset_z_m,
                                             double H,
                                             double grounded_length_m) {
  std::vector<StaticPiece> pieces;
  const double x =
      append_anchor_stretch(pieces, line, friction, seabed_offset_z_m, H, grounded_length_m);
  std::size_t first_segment = 0;
  const Line suspended = line_beyond(line, grounded_length_m, first_segment);
  for (StaticPiece piece : build_line_pieces(suspended, H, 0.0)) {
    piece.segment += first_segment;
    piece.s_begin_m += grounded_length_m;
    piece.offset_begin_m += Vec2(x, seabed_offset_z_m);
    piece.stretched_begin_m += x;
    pieces.push_back(piece);
  }
  return pieces;
}

}  // namespace catena::internal
