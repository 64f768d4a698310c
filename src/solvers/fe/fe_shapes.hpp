// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// From the `fe` chain's nodal displacements to what a user sees on the request's stations
/// (docs/explanation/methods/fe.md): displacements interpolated linearly between nodes and
/// projected on the continuous static tangent and normal (in plane), and the dynamic tension of
/// each element, tau_j = EA t_j . (D_{j+1} - D_j) / l0, interpolated linearly between element
/// midpoints.

#include <complex>
#include <vector>

#include "catena/solvers/modal_result.hpp"
#include "catena/statics/elastic_catenary.hpp"
#include "solvers/fe/fe_chain_statics.hpp"

namespace catena::internal {

/// Nodal displacements of the whole chain, fixed ends included, from the free unknowns `free`;
/// in plane (x, z) per node, out of plane (v, 0). `end_a`, `end_b`: imposed end displacements.
std::vector<Vec2> node_displacements(Plane plane,
                                     int elements,
                                     const Eigen::Ref<const Vector>& free,
                                     const Vec2& end_a = Vec2::Zero(),
                                     const Vec2& end_b = Vec2::Zero());

/// Dynamic tension of each element, tau_j = EA t_j . (D_{j+1} - D_j) / l0 [N].
Vector element_tension(const FeChain& chain, const std::vector<Vec2>& D);

/// The chain's motion on the stations: u, w (in plane) or v (out of plane), and tension when asked.
struct FeSampled {
  Vector u, w, v, tension;
};

/// Samples displacements `D` on `stations` (linear between nodes; in plane projected on the
/// continuous static tangent and normal) and, when `tau` is given, the element tensions (linear
/// between element midpoints, extrapolated linearly over the half elements at the ends).
FeSampled sample_on_stations(Plane plane,
                             const FeChain& chain,
                             const std::vector<Vec2>& D,
                             const Vector* tau,
                             const Vector& stations,
                             const StaticSolution& statics);

/// One eigenvector as a mode on the stations, normalised (modal_result.hpp convention); with
/// tension when asked (zero out of plane: out-of-plane motion causes no first-order tension).
Mode mode_on_stations(Plane plane,
                      const FeChain& chain,
                      const Eigen::Ref<const Vector>& eigenvector,
                      const Vector& stations,
                      const StaticSolution& statics,
                      bool with_tension);

/// A damped (complex) eigenvector as a mode on the stations: real parts in u, w (v), imaginary
/// parts in u_imag, w_imag (v_imag); with tension when asked, tau_j = (EA_j + c_a,j lambda)
/// t_j . (D_{j+1} - D_j) / l0 (Kelvin-Voigt), zero out of plane; normalised by
/// normalise_complex_mode on w (on u when max|w| <= 1e-6 max|u|, as the real normalisation) or v.
Mode damped_mode_on_stations(Plane plane,
                             const FeChain& chain,
                             const Eigen::VectorXcd& eigenvector,
                             std::complex<double> lambda,
                             const Vector& stations,
                             const StaticSolution& statics,
                             bool with_tension);

}  // namespace catena::internal
