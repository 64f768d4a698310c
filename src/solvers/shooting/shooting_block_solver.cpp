// SPDX-License-Identifier: MIT
// Block lower-triangular linear solves for the shot with the slope: see shooting_block_solver.hpp.
#include "solvers/shooting/shooting_block_solver.hpp"

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>

namespace catena::internal {

namespace {

struct BlockContent {
  int block = 0;
  Eigen::PartialPivLU<Eigen::MatrixXd> yy;  // M_YY
  Eigen::PartialPivLU<Eigen::MatrixXd> ss;  // M_SS
  Eigen::MatrixXd sy;                       // M_SY
  double phase = 1.0;                       // M_pp
};

BlockContent& content(SUNLinearSolver solver) {
  return *static_cast<BlockContent*>(solver->content);
}

// The square block of the dense matrix starting at (row, column).
Eigen::MatrixXd block_of(SUNMatrix matrix, int row, int column, int size) {
  Eigen::MatrixXd out(size, size);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) out(i, j) = SM_ELEMENT_D(matrix, row + i, column + j);
  }
  return out;
}

SUNLinearSolver_Type block_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID block_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int block_initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }

// LU factors of the diagonal blocks; a singular block is a recoverable failure (CVODE then
// shortens the step).
int block_setup(SUNLinearSolver solver, SUNMatrix matrix) {
  BlockContent& c = content(solver);
  const int b = c.block;
  c.yy.compute(block_of(matrix, 0, 0, b));
  c.ss.compute(block_of(matrix, b + 1, b + 1, b));
  c.sy = block_of(matrix, b + 1, 0, b);
  c.phase = SM_ELEMENT_D(matrix, b, b);
  const bool singular = c.phase == 0.0 || c.yy.matrixLU().diagonal().cwiseAbs().minCoeff() == 0.0 ||
                        c.ss.matrixLU().diagonal().cwiseAbs().minCoeff() == 0.0;
  return singular ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;
}

// x_Y = M_YY^{-1} b_Y, x_p = b_p / M_pp, x_S = M_SS^{-1} (b_S - M_SY x_Y).
int block_solve(SUNLinearSolver solver, SUNMatrix, N_Vector x, N_Vector rhs, realtype) {
  BlockContent& c = content(solver);
  const int b = c.block;
  const Eigen::Map<const Eigen::VectorXd> r(N_VGetArrayPointer(rhs), 2 * b + 1);
  Eigen::Map<Eigen::VectorXd> out(N_VGetArrayPointer(x), 2 * b + 1);
  const Eigen::VectorXd y = c.yy.solve(r.head(b));
  const Eigen::VectorXd s = c.ss.solve(r.tail(b) - c.sy * y);
  const double phase = r(b) / c.phase;
  out.head(b) = y;
  out(b) = phase;
  out.tail(b) = s;
  return SUNLS_SUCCESS;
}

int block_free(SUNLinearSolver solver) {
  if (!solver) return SUNLS_SUCCESS;
  delete static_cast<BlockContent*>(solver->content);
  solver->content = nullptr;
  SUNLinSolFreeEmpty(solver);
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver make_block_linear_solver(SUNContext context, int block) {
  SUNLinearSolver solver = SUNLinSolNewEmpty(context);
  if (!solver) return nullptr;
  solver->ops->gettype = block_type;
  solver->ops->getid = block_id;
  solver->ops->initialize = block_initialize;
  solver->ops->setup = block_setup;
  solver->ops->solve = block_solve;
  solver->ops->free = block_free;
  auto* c = new BlockContent;
  c->block = block;
  solver->content = c;
  return solver;
}

}  // namespace catena::internal
