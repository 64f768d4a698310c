// SPDX-License-Identifier: MIT
// fe operators (src/solvers/fe/fe_operators.cpp): sizes, symmetry, the lumped mass, and that
// a rigid translation of the whole chain (free nodes and ends alike) produces no elastic force.
#include "solvers/fe/fe_operators.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "catena/statics/problem_builders.hpp"

namespace catena {
namespace {

internal::FeChain taut_chain(int elements) {
  const Problem problem = make_taut_inclined_problem(0.1, 30.0, 50.0, 0.6);
  const StaticSolution statics = solve_statics(problem);
  return internal::solve_chain_statics(problem, statics, elements, problem.cable.axial_stiffness_n);
}

TEST(FeOperators, SizesSymmetryAndLumpedMass) {
  const internal::FeChain chain = taut_chain(20);
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const internal::FeMatrices matrices = internal::assemble(plane, chain);
    const int per_node = plane == Plane::InPlane ? 2 : 1;
    EXPECT_EQ(matrices.dofs_per_node, per_node);
    EXPECT_EQ(matrices.stiffness.rows(), internal::fe_unknowns(plane, 20));
    EXPECT_EQ(matrices.stiffness.rows(), per_node * 19);
    EXPECT_EQ(matrices.boundary_coupling.cols(), 2 * per_node);
    const Eigen::MatrixXd K(matrices.stiffness), M(matrices.mass);
    EXPECT_LE((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
    // Each node's mass: l0 (m t t^T + M n n^T), whose trace is l0 (m + M) in plane, l0 M out.
    const double l0 = chain.element_length_m[0];
    const double trace =
        plane == Plane::InPlane
            ? l0 * (chain.tangential_mass_kg_per_m[0] + chain.normal_mass_kg_per_m[0])
            : l0 * chain.normal_mass_kg_per_m[0];
    for (int i = 0; i < 19; ++i) {
      EXPECT_NEAR(M.block(per_node * i, per_node * i, per_node, per_node).trace(), trace,
                  1e-12 * trace);
    }
    // Block diagonal (lumped): only the node blocks are stored.
    EXPECT_EQ(matrices.mass.nonZeros(), per_node * per_node * 19);
  }
}

TEST(FeOperators, RigidTranslationCarriesNoElasticForce) {
  const internal::FeChain chain = taut_chain(30);
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const internal::FeMatrices matrices = internal::assemble(plane, chain);
    const int per_node = matrices.dofs_per_node;
    // Translation by d: free unknowns all d, ends too: K x + K_ib [d_a; d_b] = 0.
    const Vector d = per_node == 2 ? Vector(Vec2(0.3, -0.7)) : Vector::Constant(1, 0.5);
    const Vector x = d.replicate(matrices.stiffness.rows() / per_node, 1);
    const Vector ends = d.replicate(2, 1);
    const Vector force = matrices.stiffness * x + matrices.boundary_coupling * ends;
    const double scale = Eigen::MatrixXd(matrices.stiffness).cwiseAbs().maxCoeff();
    EXPECT_LE(force.cwiseAbs().maxCoeff(), 1e-12 * scale) << to_string(plane);
  }
}

// FeMatrices moves swap the sparse matrices (Eigen 3.4's have no move operations): the target
// holds exactly the source's entries, and the source is left empty, not a copy.
TEST(FeOperators, MovesTakeTheMatricesWithoutCopying) {
  const internal::FeChain chain = taut_chain(12);
  const internal::FeMatrices original = internal::assemble(Plane::InPlane, chain);
  internal::FeMatrices source = original;
  const double* stiffness_values = source.stiffness.valuePtr();
  internal::FeMatrices moved(std::move(source));
  EXPECT_EQ(moved.stiffness.valuePtr(), stiffness_values);  // the same storage, not a copy
  EXPECT_EQ(source.stiffness.nonZeros(), 0);
  internal::FeMatrices assigned;
  assigned = std::move(moved);
  EXPECT_EQ(assigned.stiffness.valuePtr(), stiffness_values);
  EXPECT_EQ(assigned.dofs_per_node, original.dofs_per_node);
  EXPECT_EQ(Eigen::MatrixXd(assigned.stiffness), Eigen::MatrixXd(original.stiffness));
  EXPECT_EQ(Eigen::MatrixXd(assigned.mass), Eigen::MatrixXd(original.mass));
  EXPECT_EQ(Eigen::MatrixXd(assigned.boundary_coupling),
            Eigen::MatrixXd(original.boundary_coupling));
}

}  // namespace
}  // namespace catena
