// SPDX-License-Identifier: MIT
// The damped roots of one fe level (src/solvers/fe/fe_quadratic_eigen.cpp) and their
// argument-principle count (fe_argument_count.cpp), against every root of a small chain from a
// dense eigensolver of the companion matrix [0 I; -M^{-1} K  -M^{-1} C] (independent of the
// Arnoldi path and of the linearisation the solver uses), with non-proportional damping (drag,
// Kelvin-Voigt): the roots to 1e-9, and the count of roots in rectangles of the lambda-plane
// exactly, also when one root inside is left out of the roots the count is told about (as if
// the eigensolver had missed it).
#include "solvers/fe/fe_quadratic_eigen.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <complex>
#include <vector>

#include "catena/statics/problem_builders.hpp"
#include "solvers/fe/fe_argument_count.hpp"
#include "solvers/fe/fe_chain_statics.hpp"
#include "solvers/fe/fe_operators.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using Complex = std::complex<double>;

struct Level {
  internal::FeChain chain;
  internal::FeMatrices matrices;
  internal::FeDampingMatrix damping;
};

// A sagging inclined cable (eps = 0.5, 30 degrees, lambda^2 = 20, m/M = 0.6) with distinct drags
// and axial damping, on `elements` elements.
Level damped_level(int elements, Plane plane) {
  Problem problem = make_taut_inclined_problem(0.5, 30.0, 20.0, 0.6);
  problem.cable.damping = {0.3, 0.9, 0.002};
  const StaticSolution statics = solve_statics(problem);
  Level level;
  level.chain =
      internal::solve_chain_statics(problem, statics, elements, problem.cable.axial_stiffness_n);
  level.matrices = internal::assemble(plane, level.chain);
  level.damping = internal::assemble_damping(plane, level.chain);
  return level;
}

std::vector<Complex> all_roots(const Level& level) {
  const Eigen::MatrixXd K(level.matrices.stiffness), M(level.matrices.mass),
      C(level.damping.damping);
  const Eigen::Index n = K.rows();
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  const Eigen::MatrixXd Minv = M.inverse();
  companion.topRightCorner(n, n).setIdentity();
  companion.bottomLeftCorner(n, n) = -Minv * K;
  companion.bottomRightCorner(n, n) = -Minv * C;
  Eigen::EigenSolver<Eigen::MatrixXd> eigen(companion, false);
  std::vector<Complex> roots(eigen.eigenvalues().data(), eigen.eigenvalues().data() + 2 * n);
  return roots;
}

int inside(const std::vector<Complex>& roots, const internal::FeCountRegion& r) {
  return static_cast<int>(std::count_if(roots.begin(), roots.end(), [&](Complex z) {
    return z.real() > r.re_min && z.real() < r.re_max && z.imag() > r.im_min && z.imag() < r.im_max;
  }));
}

TEST(FeArgumentCount, CountsTheRootsOfEveryRectangle) {
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const Level level = damped_level(24, plane);
    const std::vector<Complex> roots = all_roots(level);
    double top = 0.0;
    for (Complex z : roots) top = std::max(top, z.imag());
    internal::ComplexBandedLdlt factor;
    for (const internal::FeCountRegion region :
         {internal::FeCountRegion{-50.0, 1.0, 0.1, 10.0},
          internal::FeCountRegion{-5.0, 1.0, 0.05, 0.37 * top},
          internal::FeCountRegion{-1e4, 10.0, 1e-3, 0.81 * top},
          internal::FeCountRegion{-0.2, 0.0, 2.0, 7.5}}) {
      const int exact = inside(roots, region);
      const internal::FeArgumentCount count =
          internal::count_roots_in_rectangle(level.matrices.stiffness, level.damping.damping,
                                             level.matrices.mass, region, roots, factor);
      ASSERT_TRUE(count.ok) << count.failure;
      EXPECT_EQ(count.count, exact) << to_string(plane) << " " << region.describe();
      // A root the eigensolver missed (left out of the known ones) is still counted.
      std::vector<Complex> missing = roots;
      const auto missed = std::find_if(missing.begin(), missing.end(), [&](Complex z) {
        return inside(std::vector<Complex>{z}, region) == 1;
      });
      if (missed == missing.end()) continue;
      missing.erase(missed);
      const internal::FeArgumentCount again =
          internal::count_roots_in_rectangle(level.matrices.stiffness, level.damping.damping,
                                             level.matrices.mass, region, missing, factor);
      ASSERT_TRUE(again.ok) << again.failure;
      EXPECT_EQ(again.count, exact) << "one root unknown: " << region.describe();
    }
  }
}

// The roots of Im > 0 of smallest Im, from the dense companion matrix.
std::vector<Complex> lowest_underdamped(const std::vector<Complex>& roots, std::size_t count) {
  std::vector<Complex> upper;
  for (Complex z : roots)
    if (z.imag() > 1e-9 * std::abs(z)) upper.push_back(z);
  std::sort(upper.begin(), upper.end(), [](Complex a, Complex b) { return a.imag() < b.imag(); });
  upper.resize(std::min(count, upper.size()));
  return upper;
}

TEST(FeQuadraticEigen, LowestRootsAgreeWithTheDenseCompanionSolve) {
  // 2 (N - 1) = 98 unknowns in plane: the Arnoldi path (the dense one takes 2n <= 160).
  for (const auto& [elements, plane] :
       {std::pair{50, Plane::InPlane}, std::pair{100, Plane::OutOfPlane},
        std::pair{30, Plane::InPlane}}) {
    const Level level = damped_level(elements, plane);
    const int modes = 6;
    const internal::FeDampedEigenSolution solution = internal::solve_damped_modes(
        level.chain, plane, level.matrices, level.damping.damping, modes, 1e-10, 1000);
    ASSERT_EQ(solution.termination, Termination::Converged) << solution.message;
    EXPECT_EQ(solution.counted, modes) << solution.message;
    const std::vector<Complex> exact = lowest_underdamped(all_roots(level), modes);
    ASSERT_EQ(solution.roots.size(), modes);
    for (int i = 0; i < modes; ++i) {
      EXPECT_LE(std::abs(solution.roots[i] - exact[static_cast<std::size_t>(i)]),
                1e-9 * std::abs(exact[static_cast<std::size_t>(i)]))
          << elements << " " << i << ": " << solution.roots[i] << " vs "
          << exact[static_cast<std::size_t>(i)];
      // delta on its own.
      EXPECT_LE(std::abs(solution.roots[i].real() - exact[static_cast<std::size_t>(i)].real()),
                1e-9 * std::abs(exact[static_cast<std::size_t>(i)].real()));
    }
    EXPECT_LE(solution.max_backward_error, 1e-13);
  }
}

}  // namespace
}  // namespace catena
