// SPDX-License-Identifier: MIT
// The block linear solver of the slope shots (src/solvers/shooting/shooting_block_solver.hpp):
// on a matrix of the block lower-triangular layout [M_YY 0 0; 0 1 0; M_SY 0 M_SS] it gives the
// solution of the full dense system, for the in-plane (8) and out-of-plane (2) blocks.
#include "solvers/shooting/shooting_block_solver.hpp"

#include <gtest/gtest.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>

#include "solvers/shooting/shooting_sundials_handles.hpp"

namespace catena::internal {
namespace {

// A well-conditioned matrix of the solver's layout: I + small entries in the three blocks.
Eigen::MatrixXd block_layout_matrix(int block) {
  const int n = 2 * block + 1;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  const Eigen::MatrixXd yy = 0.3 * Eigen::MatrixXd::Random(block, block);
  const Eigen::MatrixXd sy = 0.7 * Eigen::MatrixXd::Random(block, block);
  const Eigen::MatrixXd ss = 0.3 * Eigen::MatrixXd::Random(block, block);
  M.topLeftCorner(block, block) = Eigen::MatrixXd::Identity(block, block) + yy;
  M(block, block) = 1.0;
  M.bottomLeftCorner(block, block) = sy;
  M.bottomRightCorner(block, block) = Eigen::MatrixXd::Identity(block, block) + ss;
  return M;
}

TEST(ShootingBlockSolver, SolvesTheBlockLowerTriangularSystemLikeTheFullOne) {
  for (int block : {2, 8}) {
    const int n = 2 * block + 1;
    SundialsContext context;
    ASSERT_TRUE(context.ok());
    const Eigen::MatrixXd M = block_layout_matrix(block);
    SundialsMatrix A(SUNDenseMatrix(n, n, context.get()));
    SerialVector x(n, context.get()), b(n, context.get());
    SundialsLinearSolver solver(make_block_linear_solver(context.get(), block));
    ASSERT_TRUE(A.ok() && x.ok() && b.ok() && solver.ok());
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) SM_ELEMENT_D(A.get(), i, j) = M(i, j);
    const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
    for (int i = 0; i < n; ++i) b.data()[i] = rhs[i];
    ASSERT_EQ(SUNLinSolInitialize(solver.get()), 0);
    ASSERT_EQ(SUNLinSolSetup(solver.get(), A.get()), 0);
    ASSERT_EQ(SUNLinSolSolve(solver.get(), A.get(), x.get(), b.get(), 0.0), 0);
    const Eigen::VectorXd want = M.fullPivLu().solve(rhs);
    const double scale = want.cwiseAbs().maxCoeff();
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(x.data()[i], want[i], 1e-13 * scale) << "block " << block << ", row " << i;
  }
}

}  // namespace
}  // namespace catena::internal
