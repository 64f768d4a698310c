// SPDX-License-Identifier: MIT
// fe eigenpairs of one level (src/solvers/fe/fe_eigen.cpp): the exact spectrum of a uniform
// string chain on the dense and the Lanczos paths, the Sylvester count, and the quality of the
// eigenpairs of stiff chains (M-orthogonality, residual, normwise backward error).
#include "solvers/fe/fe_eigen.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catena/statics/problem_builders.hpp"
#include "solvers/fe/fe_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::straight_bar;

using catena::testing::relative_error;

// The uniform string chain: N elements of length l under tension T, node masses mu l. Its exact
// eigenvalues are lambda_n = (4 T / (mu l^2)) sin^2(n pi / 2N).
internal::FeMatrices uniform_string(int elements, double T, double mu, double l) {
  const int n = elements - 1;
  std::vector<Eigen::Triplet<double>> k_entries, m_entries;
  for (int i = 0; i < n; ++i) {
    k_entries.emplace_back(i, i, 2.0 * T / l);
    if (i > 0) k_entries.emplace_back(i, i - 1, -T / l);
    if (i + 1 < n) k_entries.emplace_back(i, i + 1, -T / l);
    m_entries.emplace_back(i, i, mu * l);
  }
  internal::FeMatrices matrices;
  matrices.dofs_per_node = 1;
  matrices.stiffness.resize(n, n);
  matrices.stiffness.setFromTriplets(k_entries.begin(), k_entries.end());
  matrices.mass.resize(n, n);
  matrices.mass.setFromTriplets(m_entries.begin(), m_entries.end());
  return matrices;
}

double string_eigenvalue(int mode, int elements, double T, double mu, double l) {
  const double s = std::sin(mode * kPi / (2.0 * elements));
  return 4.0 * T / (mu * l * l) * s * s;
}

// Both paths (dense for <= 64 unknowns, shift-invert Lanczos above) must reproduce the exact
// discrete spectrum to near rounding: 1e-10 leaves room for the Lanczos tolerance 1e-13 and the
// conditioning of lambda_1 against lambda_max (N^2 ~ 4e4).
constexpr double kRelTolEigenvalue = 1e-10;

TEST(FeEigen, UniformStringHasItsExactSpectrumOnBothPaths) {
  for (int elements : {20, 300}) {
    const double T = 3.0, mu = 2.0, l = 1.0 / elements;
    const internal::FeMatrices matrices = uniform_string(elements, T, mu, l);
    const internal::FeEigenSolution eigen = internal::solve_lowest_modes(matrices, 6, 1e-13, 1000);
    ASSERT_EQ(eigen.termination, Termination::Converged) << eigen.message;
    ASSERT_EQ(eigen.eigenvalues.size(), 6);
    for (int i = 0; i < 6; ++i) {
      EXPECT_LE(relative_error(eigen.eigenvalues[i], string_eigenvalue(i + 1, elements, T, mu, l)),
                kRelTolEigenvalue)
          << "N = " << elements << ", mode " << i + 1;
    }
    EXPECT_EQ(eigen.inertia_count, 6);
    EXPECT_GT(eigen.inertia_shift, eigen.eigenvalues[5]);
    EXPECT_LT(eigen.inertia_shift, string_eigenvalue(7, elements, T, mu, l));
  }
}

TEST(FeEigen, SylvesterCountBetweenEigenvalues) {
  const int elements = 100;
  const double T = 1.0, mu = 1.0, l = 0.01;
  const internal::FeMatrices matrices = uniform_string(elements, T, mu, l);
  for (int below : {0, 1, 3, 10}) {
    const double shift = below == 0 ? 0.5 * string_eigenvalue(1, elements, T, mu, l)
                                    : 0.5 * (string_eigenvalue(below, elements, T, mu, l) +
                                             string_eigenvalue(below + 1, elements, T, mu, l));
    EXPECT_EQ(internal::count_eigenvalues_below(matrices, shift), below);
  }
}

// The eigenpairs must be far more accurate than the discretisation error they feed (>= 1e-9
// relative in omega for these meshes): mass-orthogonality and relative residual 1e-10. The
// relative residual ||K phi - w^2 M phi|| / ||K phi|| has a rounding floor of about
// eps ||K|| / ||K phi|| ~ eps (EA / T) (2N / (pi n))^2, so it can hold only where the chain is not
// stiff: out of plane (no EA) and in plane for a small EA/T (the straight bar, EA/T = 10). For a
// stiff chain the normwise backward error ||r|| / ((||K|| + w^2 ||M||) ||phi||) is the measure
// that reaches rounding.
constexpr double kMaxOrthogonalityError = 1e-10;
constexpr double kMaxResidual = 1e-10;
constexpr double kMaxBackwardError = 1e-14;

internal::FeEigenSolution lowest_modes(const Problem& problem, Plane plane, int elements) {
  const StaticSolution statics = solve_statics(problem);
  const internal::FeChain chain =
      internal::solve_chain_statics(problem, statics, elements, problem.cable.axial_stiffness_n);
  return internal::solve_lowest_modes(internal::assemble(plane, chain), 10, 1e-13, 1000);
}

TEST(FeEigen, ModesAreMassOrthogonalWithSmallResidualAndBackwardError) {
  const Problem inclined = make_taut_inclined_problem(0.1, 30.0, 50.0, 0.6);  // EA/T = 6667
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const internal::FeEigenSolution eigen = lowest_modes(inclined, plane, 800);
    ASSERT_EQ(eigen.termination, Termination::Converged) << eigen.message;
    EXPECT_LE(eigen.max_orthogonality_error, kMaxOrthogonalityError);
    EXPECT_LE(eigen.max_backward_error, kMaxBackwardError);
    EXPECT_EQ(eigen.inertia_count, 10);
    if (plane == Plane::OutOfPlane) {
      EXPECT_LE(eigen.max_residual, kMaxResidual);
    }
  }
  const internal::FeEigenSolution bar = lowest_modes(straight_bar(), Plane::InPlane, 400);
  ASSERT_EQ(bar.termination, Termination::Converged) << bar.message;
  EXPECT_LE(bar.max_residual, kMaxResidual);
  EXPECT_LE(bar.max_orthogonality_error, kMaxOrthogonalityError);
}

TEST(FeEigen, ModeSumGuessInterpolatesOntoTheMeshTwiceAsFine) {
  // Two in-plane modes on 3 free coarse nodes (N = 4): the guess sums them; on N = 8 (7 free
  // nodes) the even fine nodes take the coarse values, the odd ones the mean of their neighbours,
  // with the fixed end nodes at zero.
  Eigen::MatrixXd modes(6, 2);
  modes.col(0) << 1.0, 2.0, 3.0, 4.0, 5.0, 6.0;
  modes.col(1) << 1.0, 0.0, 1.0, 0.0, 1.0, 0.0;
  const Vector same = internal::mode_sum_guess(modes, 2, 6);
  ASSERT_EQ(same.size(), 6);
  EXPECT_EQ(same[0], 2.0);
  EXPECT_EQ(same[5], 6.0);
  const Vector fine = internal::mode_sum_guess(modes, 2, 14);
  ASSERT_EQ(fine.size(), 14);
  // The sums (x, z) at coarse nodes 1, 2, 3 are (2, 2), (4, 4), (6, 6); fine nodes 1..7:
  const std::vector<double> fine_x = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 3.0}, fine_z = fine_x;
  for (int node = 0; node < 7; ++node) {
    EXPECT_DOUBLE_EQ(fine[2 * node], fine_x[static_cast<std::size_t>(node)])
        << "x at fine node " << node + 1;
    EXPECT_DOUBLE_EQ(fine[2 * node + 1], fine_z[static_cast<std::size_t>(node)])
        << "z at fine node " << node + 1;
  }
  EXPECT_EQ(internal::mode_sum_guess(modes, 2, 10).size(), 0);
}

// One FeEigenWorkspace for several solves (as fe's levels share it: a smaller solve after a
// larger one, then the larger again) gives the same eigenpairs and inertia, bit for bit, as a
// fresh workspace per solve: reused memory carries nothing from one solve into the next.
TEST(FeEigen, ASharedWorkspaceChangesNoResult) {
  const Problem problem = make_taut_inclined_problem(0.1, 30.0, 50.0, 0.6);
  const StaticSolution statics = solve_statics(problem);
  internal::FeEigenWorkspace shared;  // the banded factor
  for (int elements : {400, 200, 400}) {
    const internal::FeMatrices matrices = internal::assemble(
        Plane::InPlane,
        internal::solve_chain_statics(problem, statics, elements, problem.cable.axial_stiffness_n));
    const internal::FeEigenSolution fresh = internal::solve_lowest_modes(matrices, 10, 1e-13, 1000);
    const internal::FeEigenSolution reused =
        internal::solve_lowest_modes(matrices, 10, 1e-13, 1000, &shared);
    ASSERT_EQ(reused.termination, Termination::Converged) << reused.message;
    EXPECT_EQ(reused.eigenvalues, fresh.eigenvalues) << "N = " << elements;
    EXPECT_EQ(reused.eigenvectors, fresh.eigenvectors) << "N = " << elements;
    EXPECT_EQ(reused.inertia_count, fresh.inertia_count);
    EXPECT_EQ(reused.inertia_shift, fresh.inertia_shift);
  }
}

}  // namespace
}  // namespace catena
