// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// The `fe` chain's operators (docs/explanation/methods/fe.md): sparse stiffness K and lumped mass
/// M of one plane on the free (interior) nodes, and the coupling of the free unknowns to the end
/// nodes (for an imposed end displacement). In plane the element tangent stiffness is (EA/l0) t t^T
/// + (T/l)(I - t t^T) and the node mass l0 (m t t^T + M n n^T) about the bisecting node tangent
/// (block tridiagonal, 2x2 blocks); out of plane T/l and M l0 (tridiagonal). On a line a node
/// between two sections carries half of each element's mass, and a point attachment's inertia is
/// added on its node (docs/explanation/physics.md, "General lines").

#include <Eigen/Sparse>
#include <utility>
#include <vector>

#include "catena/core/types.hpp"
#include "solvers/fe/fe_chain_statics.hpp"

namespace catena::internal {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Stiffness and mass of one plane on the free (interior) nodes. Moves swap the matrices: Eigen
/// 3.4's SparseMatrix has no move constructor or assignment, so the implicit ones would copy
/// every entry into fresh pages (at N = 1e6 in plane, 60 MB per level).
struct FeMatrices {
  FeMatrices() = default;
  FeMatrices(const FeMatrices&) = default;
  FeMatrices& operator=(const FeMatrices&) = default;
  FeMatrices(FeMatrices&& other) noexcept { swap(other); }
  FeMatrices& operator=(FeMatrices&& other) noexcept {
    swap(other);
    return *this;
  }
  void swap(FeMatrices& other) noexcept {
    std::swap(dofs_per_node, other.dofs_per_node);
    stiffness.swap(other.stiffness);
    mass.swap(other.mass);
    boundary_coupling.swap(other.boundary_coupling);
  }

  /// Unknowns per node: 2 in plane (x, z), 1 out of plane.
  int dofs_per_node = 2;
  SparseMatrix stiffness;
  SparseMatrix mass;
  /// Coupling K_ib of the free unknowns to the end node's unknowns (columns: node a then node b,
  /// dofs_per_node each), for the forced response.
  SparseMatrix boundary_coupling;
};

FeMatrices assemble_inplane(const FeChain& chain);
FeMatrices assemble_outofplane(const FeChain& chain);
/// assemble_inplane or assemble_outofplane.
FeMatrices assemble(Plane plane, const FeChain& chain);

/// The seabed foundation in plane on each node 0..N (docs/explanation/methods/fe.md, "Seabed
/// contact"), lumped like the mass: node i carries k times half of each grounded neighbour's l0,
/// k_t on x (along the seabed) and k_s on z; the end nodes carry none. Empty without contact.
std::vector<Eigen::Matrix2d> inplane_foundation(const FeChain& chain);

/// The damping matrix C of one plane on the free nodes (docs/explanation/methods/fe.md, "Damping"),
/// assembled like the operators beside it: the drag lumped per node like the mass, l0 (c_t t t^T
/// + c_n n n^T) about the node tangent in plane (each half element in its own frame at a joint) and
/// c_n l0 out of plane; the Kelvin-Voigt axial damping per element like the axial stiffness,
/// (c_a / l0) t t^T (in plane only); the seabed dashpot c_s on the grounded nodes' z, lumped like
/// k_s. Point attachments carry no damping. Same block-tridiagonal pattern as the stiffness.
struct FeDampingMatrix {
  SparseMatrix damping;
  /// Coupling C_ib of the free unknowns to the end nodes (as FeMatrices::boundary_coupling).
  SparseMatrix boundary_coupling;
};
FeDampingMatrix assemble_damping(Plane plane, const FeChain& chain);

/// Number of free unknowns of a chain of `elements` elements in `plane`: 2 (N - 1) or N - 1.
int fe_unknowns(Plane plane, int elements);

}  // namespace catena::internal
