// How fe meshes a line: see fe_line_mesh.hpp and docs/methods/fe.md.
#include "solvers/internal/fe_line_mesh.hpp"

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
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t k = 0; given < elements && k < order.size(); ++k, ++given) ++counts[order[k]];
  for (int& count : counts) count = std::max(count, 1);
  return counts;
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
    // A line lying entirely on the seabed ends with an empty suspended piece.
    if (!(source.section.length_m > 0.0)) continue;
    FeMeshPiece piece;
    piece.segment = source.segment;
    piece.section = line.segments[source.segment];
    piece.section.length_m = source.section.length_m;
    piece.point_at_start = p == 0 ? -1 : point_at(line, source.s_begin_m);
    piece.grounded = source.grounded;
    piece.grounded_tension_begin_n = source.grounded_tension_begin_n;
    mesh.pieces.push_back(piece);
    lengths.push_back(piece.section.length_m);
  }
  const std::vector<int> counts = proportional_counts(lengths, elements);
  for (std::size_t p = 0; p < counts.size(); ++p) mesh.pieces[p].elements = counts[p];
  return mesh;
}

}  // namespace catena::internal
