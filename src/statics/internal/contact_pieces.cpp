// SPDX-License-Identifier: MIT
// The pieces of a line in general seabed contact: see contact_pieces.hpp.
#include "statics/internal/contact_pieces.hpp"

#include <algorithm>
#include <cmath>

#include "statics/internal/catenary_segment.hpp"
#include "statics/internal/line_parts.hpp"
#include "statics/internal/line_pieces.hpp"
#include "statics/internal/seabed_pieces.hpp"

namespace catena::internal {
namespace {

// Index of the segment containing s (at a joint: the one toward B).
std::size_t segment_at(const Line& line, double s) {
  const double merge = merge_distance(line);
  std::size_t k = 0;
  while (k + 1 < line.segments.size() && line.segment_start_m(k + 1) <= s + merge) ++k;
  return k;
}

// The state of the assembly: where the next piece starts.
struct Cursor {
  double s = 0.0;
  double x = 0.0;
  double stretched = 0.0;
};

// Appends the grounded stretch [cursor.s, s_end) with tension H all along (friction not
// mobilised between two suspended parts), cut at joints and points and, when heap > 0, at
// s_end - heap: the part beyond lies in a heap (its x does not advance).
void append_level_stretch(std::vector<StaticPiece>& pieces,
                          const Line& line,
                          double seabed_z,
                          double H,
                          double s_end,
                          double heap,
                          Cursor& cursor) {
  const double merge = merge_distance(line);
  std::vector<double> cuts{cursor.s, s_end};
  for (std::size_t k = 1; k < line.segments.size(); ++k) cuts.push_back(line.segment_start_m(k));
  for (const PointAttachment& point : line.points) cuts.push_back(point.s_m);
  const double heap_start = s_end - heap;
  if (heap > 0.0) cuts.push_back(heap_start);
  std::sort(cuts.begin(), cuts.end());
  std::vector<double> kept;
  for (double cut : cuts) {
    if (cut < cursor.s || cut > s_end - merge) continue;
    if (kept.empty() || cut > kept.back() + merge) kept.push_back(cut);
  }
  kept.push_back(s_end);
  for (std::size_t i = 0; i + 1 < kept.size(); ++i) {
    const std::size_t k = segment_at(line, kept[i]);
    const double length = kept[i + 1] - kept[i];
    StaticPiece piece{section_of(line.segments[k], length),
                      k,
                      kept[i],
                      0.0,
                      Vec2(cursor.x, seabed_z),
                      cursor.stretched};
    piece.grounded = true;
    piece.grounded_tension_begin_n = H;
    piece.slack_heap = heap > 0.0 && kept[i] >= heap_start - merge;
    const double stretched = grounded_stretched_increment(piece, length);
    if (!piece.slack_heap) cursor.x += stretched;
    cursor.stretched += stretched;
    pieces.push_back(piece);
  }
  cursor.s = s_end;
}

// Appends the suspended arc and returns the height of its end above the seabed.
double append_arc(std::vector<StaticPiece>& pieces,
                  const Line& line,
                  const ContactArc& arc,
                  double seabed_z,
                  double H,
                  Cursor& cursor) {
  const double V_begin = arc.from_a ? -weight_between(line, 0.0, arc.s_end_m) : 0.0;
  const double z_begin = arc.from_a ? 0.0 : seabed_z;
  std::size_t first_segment = 0;
  const Line part = line_between(line, arc.s_begin_m, arc.s_end_m, first_segment);
  const std::vector<StaticPiece> arc_pieces = build_line_pieces(part, H, V_begin);
  for (StaticPiece piece : arc_pieces) {
    piece.segment += first_segment;
    piece.s_begin_m += arc.s_begin_m;
    piece.offset_begin_m += Vec2(cursor.x, z_begin);
    piece.stretched_begin_m += cursor.stretched;
    pieces.push_back(piece);
  }
  const StaticPiece& last = arc_pieces.back();
  const Vec2 end = line_end_offset(arc_pieces, H);
  cursor.stretched +=
      last.stretched_begin_m +
      stretched_increment(last.section, H, last.vertical_begin_n, last.section.length_m);
  cursor.x += end.x();
  cursor.s = arc.s_end_m;
  return z_begin + end.y() - seabed_z;
}

}  // namespace

ContactPieces build_contact_pieces(const ContactGeometry& geometry,
                                   double friction,
                                   double seabed_offset_z_m,
                                   double H,
                                   const std::vector<ContactArc>& arcs,
                                   double heap_length_m) {
  const Line& line = geometry.line;
  ContactPieces result;
  Cursor cursor;
  for (const ContactArc& arc : arcs) {
    if (arc.s_begin_m > cursor.s) {
      const double heap = arc.to_b ? heap_length_m : 0.0;
      if (cursor.s == 0.0 && H > 0.0) {
        // The stretch from an anchor lying on the seabed: the friction law (as with one contact).
        cursor.x = append_anchor_stretch(result.pieces, line, friction, seabed_offset_z_m, H,
                                         arc.s_begin_m);
        cursor.stretched = cursor.x;
        cursor.s = arc.s_begin_m;
      } else {
        append_level_stretch(result.pieces, line, seabed_offset_z_m, H, arc.s_begin_m, heap,
                             cursor);
      }
    }
    const double miss = append_arc(result.pieces, line, arc, seabed_offset_z_m, H, cursor);
    if (!arc.to_b) result.touchdown_miss_m = std::max(result.touchdown_miss_m, std::abs(miss));
  }
  return result;
}

}  // namespace catena::internal
