// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Richardson extrapolation in h of the `fe` forced response (docs/explanation/methods/fe.md,
/// "Forced response"), done where the two meshes' values describe the same point. The lumped
/// chain's nodal displacements converge as O(h^2) at the nodes, and its element tensions as O(h^2)
/// at the element midpoints; sampling either on the request's stations by linear interpolation adds
/// an O(h^2) error whose coefficient depends on where a station falls between grid points, which
/// differs between the meshes, so extrapolating station by station would not cancel it. Instead:
/// displacements are extrapolated at the coarse mesh's nodes (which are nodes of the fine mesh),
/// tensions at the coarse mesh's element midpoints (the fine mesh's tensions brought there by
/// cubic interpolation, O(h^4)), and the extrapolated fields are sampled on the stations by cubic
/// interpolation (O(h^4)).

#include <vector>

#include "catena/core/types.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "solvers/fe/fe_shapes.hpp"

namespace catena::internal {

/// A stretch of the mesh with equal elements (a piece of a line, fe_line_mesh.hpp; the whole of a
/// uniform cable): elements first_element .. first_element + elements - 1, node k of the piece at
/// s = start_m + k element_length_m (unstretched). The response is smooth only within a piece (its
/// slope and, at a point, its tension jump at the piece ends), so interpolation stays inside one.
struct FeFieldPiece {
  int first_element = 0;
  int elements = 0;
  double start_m = 0.0;
  double element_length_m = 0.0;
};

/// One mesh's forced response before sampling: the displacement of every node (ends included;
/// in plane (x, z), out of plane (v, 0)) and, in plane, every element's dynamic tension.
struct FeResponseField {
  std::vector<FeFieldPiece> pieces;  // in order from A; one for a uniform cable
  std::vector<Vec2> nodes;
  Vector tension;  // empty out of plane
};

/// Value at `x` of the data `values[k]` given at `first + k spacing`, by Lagrange interpolation
/// through the 4 nearest points (fewer when there are fewer; extrapolating past the ends by the
/// same polynomial). Exact for cubics.
double cubic_interpolate(const std::vector<double>& values, double first, double spacing, double x);
/// The same on `count` values starting at `values`.
double cubic_interpolate(
    const double* values, std::size_t count, double first, double spacing, double x);

/// Linear extrapolation to kappa = 0 of the fields at kappa (`at_kappa`) and 2 kappa: 2a - b.
FeResponseField extrapolate_field_in_kappa(const FeResponseField& at_kappa,
                                           const FeResponseField& at_2kappa);

/// The quadratic in kappa through the fields at kappa, 2 kappa and 4 kappa, at kappa = 0:
/// (8a - 6b + c) / 3. Its distance from the linear extrapolation is the latter's O(kappa^2) error.
FeResponseField quadratic_field_in_kappa(const FeResponseField& at_kappa,
                                         const FeResponseField& at_2kappa,
                                         const FeResponseField& at_4kappa);

/// Richardson in h for order 2 and mesh ratio 2, (4 fine - coarse) / 3, on the coarse mesh's nodes
/// and element midpoints. `fine` must have the same pieces with exactly twice the elements each.
FeResponseField richardson_field(const FeResponseField& coarse, const FeResponseField& fine);

/// The field on the stations, by cubic interpolation: displacements projected on the continuous
/// static tangent and normal in plane; the tension (zero out of plane).
FeSampled sample_field(Plane plane,
                       const FeResponseField& field,
                       const Vector& stations,
                       const StaticSolution& statics);

/// max over the stations of |a - b| for the tension (in plane) or the displacements.
double max_station_difference(const FeSampled& a, const FeSampled& b, bool tension);

}  // namespace catena::internal
