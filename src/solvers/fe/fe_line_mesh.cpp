// SPDX-License-Identifier: MIT
// How fe meshes a line: see fe_line_mesh.hpp and docs/explanation/methods/fe.md.
#include "solvers/fe/fe_line_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace catena::internal {
namespace {

// The point attachment at arc length s (within 1e-9 L, the smallest spacing Line::validate
// allows), or -1.
int point_at(const Line& line, double s) {
  const double tolerance = 1e-9 * line.length_m();
  for (std::size_t i = 0; i < line.points.size(); ++i)
    if (std::abs(line.points[i].s_m - s) <= tolerance) return static_cast<int>(i);
  return -1;
}

// Element counts proportional to `lengths`, summing to `elements` (largest remainder), each >= 1.
std::vector<int> proportional_counts(const std::vector<double>& lengths, int elements) {
  const double total = std::accumulate(lengths.begin(), lengths.end(), 0.0);
  std::vector<int> counts(lengths.size());
  std::vector<double> remainder(lengths.size());
  int given = 0;
  for (std::size_t p = 0; p < lengths.size(); ++p) {
    const double share = elements * lengths[p] / total;
    counts[p] = static_cast<int>(std::floor(share));
    remainder[p] = share - counts[p];
    given += counts[p];
  }
  std::vector<std::size_t> order(lengths.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t k = 0; given < elements && k < order.size(); ++k, ++given) ++counts[order[k]];
  for (int& count : counts) count = std::max(count, 1);
  return counts;
}

// The grounded part's transverse motion decays away from a contact boundary (a touchdown or
// lift-off point) within delta = sqrt(T / k) (tension over foundation stiffness), far shorter than
// the line's elements when k is large. The kTouchdownLayerWidths delta next to every contact
// boundary, on the grounded side, become a piece of their own with elements of delta /
// kTouchdownLayerElementsPerWidth (docs/explanation/methods/fe.md, "Seabed contact"): the layer's
// share of the discretisation error then no longer depends on k.
constexpr double kTouchdownLayerWidths = 10.0;
constexpr double kTouchdownLayerElementsPerWidth = 32.0;

// Splits the layer off grounded piece `index` at its end (`at_end`, the boundary toward B) or at
// its start; returns the number of pieces inserted (0 or 1).
int split_layer(FeLineMesh& mesh, std::size_t index, bool at_end) {
  FeMeshPiece& piece = mesh.pieces[index];
  const double k =
      std::max(mesh.seabed->stiffness_n_per_m2, mesh.seabed->tangential_stiffness_n_per_m2);
  const double length = piece.section.length_m;
  const double slope = piece.grounded_tension_slope_n_per_m;
  const double boundary_tension = piece.grounded_tension_begin_n + (at_end ? slope * length : 0.0);
  if (!(k > 0.0) || !(boundary_tension > 0.0)) return 0;
  const double delta = std::sqrt(boundary_tension / k);
  const double layer = kTouchdownLayerWidths * delta;
  const int layer_elements =
      static_cast<int>(std::ceil(kTouchdownLayerElementsPerWidth * layer / delta));
  if (layer >= 0.5 * length) {
    piece.elements =
        std::max(piece.elements,
                 static_cast<int>(std::ceil(kTouchdownLayerElementsPerWidth * length / delta)));
    return 0;
  }
  FeMeshPiece near = piece;
  near.section.length_m = layer;
  near.elements = layer_elements;
  const int rest_elements =
      std::max(1, static_cast<int>(std::lround(piece.elements * (length - layer) / length)));
  piece.section.length_m = length - layer;
  piece.elements = rest_elements;
  if (at_end) {
    near.point_at_start = -1;
    near.grounded_tension_begin_n = piece.grounded_tension_begin_n + slope * (length - layer);
    mesh.pieces.insert(mesh.pieces.begin() + static_cast<std::ptrdiff_t>(index) + 1, near);
  } else {
    piece.point_at_start = -1;
    piece.grounded_tension_begin_n += slope * layer;
    mesh.pieces.insert(mesh.pieces.begin() + static_cast<std::ptrdiff_t>(index), near);
  }
  return 1;
}

// The layer at every contact boundary: the end of each grounded stretch followed by a suspended
// piece, and the start of each one preceded by a suspended piece (a middle stretch has both).
void refine_touchdown_layers(FeLineMesh& mesh) {
  for (std::size_t p = 0; p < mesh.pieces.size(); ++p) {
    if (!mesh.pieces[p].grounded) continue;
    const std::size_t first = p;
    while (p + 1 < mesh.pieces.size() && mesh.pieces[p + 1].grounded) ++p;
    const bool suspended_after = p + 1 < mesh.pieces.size();
    const bool suspended_before = first > 0;
    // The end first: the split keeps `first` where it is.
    if (suspended_after) p += static_cast<std::size_t>(split_layer(mesh, p, true));
    if (suspended_before) p += static_cast<std::size_t>(split_layer(mesh, first, false));
  }
}

}  // namespace

int FeLineMesh::elements() const {
  int total = 0;
  for (const FeMeshPiece& piece : pieces) total += piece.elements;
  return total;
}

FeLineMesh FeLineMesh::refined(int factor) const {
  FeLineMesh out = *this;
  for (FeMeshPiece& piece : out.pieces) piece.elements *= factor;
  return out;
}

std::optional<FeLineMesh> FeLineMesh::halved() const {
  FeLineMesh out = *this;
  for (FeMeshPiece& piece : out.pieces) {
    if (piece.elements % 2 != 0) return std::nullopt;
    piece.elements /= 2;
  }
  return out;
}

FeLineMesh FeLineMesh::evened() const {
  FeLineMesh out = *this;
  for (FeMeshPiece& piece : out.pieces) piece.elements += piece.elements % 2;
  return out;
}

FeLineMesh uniform_cable_mesh(const CableProperties& cable, int elements) {
  FeLineMesh mesh;
  FeMeshPiece piece;
  piece.section = line_of_cable(cable).segments.front();
  piece.elements = elements;
  mesh.pieces.push_back(piece);
  return mesh;
}

bool meshed_as_one_piece(const Problem& problem, const StaticSolution& statics) {
  return (problem.is_uniform() && !statics.has_contact()) || statics.pieces().empty();
}

FeLineMesh make_line_mesh(const Problem& problem, const StaticSolution& statics, int elements) {
  if (meshed_as_one_piece(problem, statics)) return uniform_cable_mesh(problem.cable, elements);
  const Line line = problem.as_line();
  FeLineMesh mesh;
  mesh.points = line.points;
  if (statics.has_contact()) mesh.seabed = statics.seabed();
  std::vector<double> lengths;
  for (std::size_t p = 0; p < statics.pieces().size(); ++p) {
    const StaticPiece& source = statics.pieces()[p];
    // A line lying entirely on the seabed ends with an empty suspended piece (the statics may
    // leave other empty pieces at a contact boundary too).
    if (!(source.section.length_m > 0.0)) continue;
    FeMeshPiece piece;
    piece.segment = source.segment;
    piece.section = line.segments[source.segment];
    piece.section.length_m = source.section.length_m;
    piece.point_at_start = p == 0 ? -1 : point_at(line, source.s_begin_m);
    piece.grounded = source.grounded;
    piece.grounded_tension_begin_n = source.grounded_tension_begin_n;
    piece.grounded_tension_slope_n_per_m = source.grounded_tension_slope_n_per_m;
    mesh.pieces.push_back(piece);
    lengths.push_back(piece.section.length_m);
  }
  const std::vector<int> counts = proportional_counts(lengths, elements);
  for (std::size_t p = 0; p < counts.size(); ++p) mesh.pieces[p].elements = counts[p];
  if (mesh.seabed) refine_touchdown_layers(mesh);
  return mesh;
}

}  // namespace catena::internal
