// SPDX-License-Identifier: MIT
// Pieces of a general line's statics: see line_pieces.hpp.
#include "statics/internal/line_pieces.hpp"

#include "statics/internal/catenary_segment.hpp"

namespace catena::internal {

CableProperties section_of(const LineSegment& segment, double length_m) {
  CableProperties section;
  section.length_m = length_m;
  section.weight_n_per_m = segment.weight_n_per_m;
  section.axial_stiffness_n = segment.axial_stiffness_n;
  section.mass_kg_per_m = segment.mass_kg_per_m;
  section.added_mass_kg_per_m = segment.added_mass_kg_per_m;
  section.damping = segment.damping;
  section.added_mass_tangential_kg_per_m = segment.added_mass_tangential_kg_per_m;
  section.drag = segment.drag;
  return section;
}

namespace {

// Appends a piece starting at `s` with start state (V, r, stretched) and advances the state to
// its end.
void append_piece(std::vector<StaticPiece>& pieces,
                  const LineSegment& segment,
                  std::size_t index,
                  double s,
                  double length,
                  double H,
                  double& V,
                  Vec2& r,
                  double& stretched) {
  StaticPiece piece{section_of(segment, length), index, s, V, r, stretched};
  r += offset(piece.section, H, V, length);
  stretched += stretched_increment(piece.section, H, V, length);
  V += segment.weight_n_per_m * length;
  pieces.push_back(piece);
}

}  // namespace

std::vector<StaticPiece> build_line_pieces(const Line& line, double H, double V_A) {
  std::vector<StaticPiece> pieces;
  // A point within `merge` of a joint acts at the joint (no sliver piece).
  const double merge = 1e-12 * line.length_m();
  double V = V_A;
  Vec2 r = Vec2::Zero();
  double stretched = 0.0;
  std::size_t next_point = 0;
  double cursor = 0.0;
  for (std::size_t k = 0; k < line.segments.size(); ++k) {
    const double end = cursor + line.segments[k].length_m;
    for (;;) {
      while (next_point < line.points.size() && line.points[next_point].s_m <= cursor + merge) {
        V += line.points[next_point++].weight_n;
      }
      const bool cut = next_point < line.points.size() && line.points[next_point].s_m < end - merge;
      const double stop = cut ? line.points[next_point].s_m : end;
      append_piece(pieces, line.segments[k], k, cursor, stop - cursor, H, V, r, stretched);
      cursor = stop;
      if (!cut) break;
    }
    cursor = end;
  }
  return pieces;
}

Vec2 line_end_offset(const std::vector<StaticPiece>& pieces, double H) {
  const StaticPiece& last = pieces.back();
  return last.offset_begin_m +
         offset(last.section, H, last.vertical_begin_n, last.section.length_m);
}

Eigen::Matrix2d line_end_jacobian(const std::vector<StaticPiece>& pieces, double H) {
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  for (const StaticPiece& piece : pieces)
    J += offset_jacobian(piece.section, H, piece.vertical_begin_n);
  return J;
}

}  // namespace catena::internal
