#pragma once
/// \file
/// Richardson extrapolation in h of the `fe` forced response (docs/methods/fe.md, "Forced
/// response"), done where the two meshes' values describe the same point. The lumped chain's nodal
/// displacements converge as O(h^2) at the nodes, and its element tensions as O(h^2) at the element
/// midpoints; sampling either on the request's stations by linear interpolation adds an O(h^2)
/// error whose coefficient depends on where a station falls between grid points, which differs
/// between the meshes, so extrapolating station by station would not cancel it. Instead:
/// displacements are extrapolated at the coarse mesh's nodes (which are nodes of the fine mesh),
/// tensions at the coarse mesh's element midpoints (the fine mesh's tensions brought there by
/// cubic interpolation, O(h^4)), and the extrapolated fields are sampled on the stations by cubic
/// interpolation (O(h^4)).

#include <vector>

#include "catena/core/types.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "solvers/internal/fe_shapes.hpp"

namespace catena::internal {

/// One mesh's forced response before sampling: the displacement of every node (ends included;
/// in plane (x, z), out of plane (v, 0)) and, in plane, every element's dynamic tension.
struct FeResponseField {
  /// One piece of equal elements: its first element, element count, start s and l0 [m].
  struct Piece {
    std::size_t first = 0;
    std::size_t elements = 0;
    double s_begin_m = 0.0;
    double element_length_m = 0.0;
  };
  /// The pieces from A (one for a uniform cable). Every interpolation stays within one piece, so
  /// that the kinks of the response at joints, points and the touchdown point do not spoil it.
  std::vector<Piece> pieces;
  std::vector<Vec2> nodes;
  Vector tension;  // empty out of plane
};

/// Value at `x` of the data `values[k]` given at `first + k spacing`, by Lagrange interpolation
/// through the 4 nearest points (fewer when there are fewer; extrapolating past the ends by the
/// same polynomial). Exact for cubics.
double cubic_interpolate(const std::vector<double>& values, double first, double spacing, double x);

/// Linear extrapolation to kappa = 0 of the fields at kappa (`at_kappa`) and 2 kappa: 2a - b.
FeResponseField extrapolate_field_in_kappa(const FeResponseField& at_kappa, const FeResponseField& at_2kappa);

/// Richardson in h for order 2 and mesh ratio 2, (4 fine - coarse) / 3, on the coarse mesh's nodes
/// and element midpoints. `fine` must have the same pieces with twice the elements each.
FeResponseField richardson_field(const FeResponseField& coarse, const FeResponseField& fine);

/// The field on the stations, by cubic interpolation: displacements projected on the continuous
/// static tangent and normal in plane; the tension (zero out of plane).
FeSampled sample_field(Plane plane, const FeResponseField& field, const Vector& stations,
                       const StaticSolution& statics);

/// max over the stations of |a - b| for the tension (in plane) or the displacements.
double max_station_difference(const FeSampled& a, const FeSampled& b, bool tension);

}  // namespace catena::internal
