// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// How the `fe` chain meshes a line (docs/explanation/methods/fe.md, "Lines"): the line is cut into
/// pieces at every joint and point attachment (the pieces of the statics), each piece gets its own
/// element count, proportional to its length and at least one, and a finer level doubles every
/// count, so that node i of a mesh is node 2i of the next (the node mapping of
/// fe_extrapolation.hpp).

#include <optional>
#include <vector>

#include "catena/models/cable.hpp"
#include "catena/statics/elastic_catenary.hpp"

namespace catena::internal {

/// One piece of the mesh: a stretch of one segment, meshed with `elements` equal elements.
struct FeMeshPiece {
  /// The piece's section; its length_m is the piece's unstretched length.
  LineSegment section;
  /// Index of the segment in Line::segments.
  std::size_t segment = 0;
  int elements = 1;
  /// Index in Line::points of the point attachment at the piece's start (-1: none).
  int point_at_start = -1;
  /// True for a piece resting on the seabed (StaticPiece::grounded); its static tension is
  /// max(grounded_tension_begin_n + grounded_tension_slope_n_per_m (s - s_begin), 0)
  /// (docs/explanation/physics.md, "Seabed contact").
  bool grounded = false;
  double grounded_tension_begin_n = 0.0;
  double grounded_tension_slope_n_per_m = 0.0;
};

/// The pieces of one mesh, in order from A, and the line's point attachments.
struct FeLineMesh {
  std::vector<FeMeshPiece> pieces;
  std::vector<PointAttachment> points;
  /// The seabed when the line rests on it (grounded pieces anywhere), else empty.
  std::optional<Seabed> seabed;

  /// Total number of elements.
  int elements() const;
  /// The same pieces with every element count multiplied by `factor`.
  FeLineMesh refined(int factor) const;
  /// The same pieces with every element count halved; nullopt when a count is odd (the halved
  /// mesh's nodes would not all be nodes of this one).
  std::optional<FeLineMesh> halved() const;
  /// The same pieces with every odd element count raised by one, so that the mesh can be halved.
  FeLineMesh evened() const;
  /// True for one piece (a uniform cable, or a line of one segment and no points).
  bool is_one_piece() const { return pieces.size() == 1; }
};

/// The one-piece mesh of a uniform cable with `elements` elements.
FeLineMesh uniform_cable_mesh(const CableProperties& cable, int elements);

/// True when `problem` is meshed as one piece: a uniform cable that does not rest on a seabed.
bool meshed_as_one_piece(const Problem& problem, const StaticSolution& statics);

/// The mesh of `problem` with about `elements` elements: a uniform cable gets exactly that many; a
/// line's pieces (and those of a cable resting on the seabed, whose contact boundaries and
/// zero-tension points are cuts of the statics, hence nodes) (statics.pieces()) share them in
/// proportion to their lengths (largest remainder), each getting at least one, so the total can
/// exceed `elements` by the pieces that are too short for their share. With a seabed foundation,
/// the grounded side of every contact boundary gets a layer piece of its own (fe.md, "Seabed
/// contact").
FeLineMesh make_line_mesh(const Problem& problem, const StaticSolution& statics, int elements);

}  // namespace catena::internal
