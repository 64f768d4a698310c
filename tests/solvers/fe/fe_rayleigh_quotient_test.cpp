// SPDX-License-Identifier: MIT
// The element-wise Rayleigh quotient of fe modes (src/solvers/fe/fe_rayleigh_quotient.hpp):
// - it is the assembled quotient phi^T K phi / phi^T M phi (taut chain, a grounded line with its
//   foundation, both planes);
// - on a stiff chain (EA/T = 1e6, N = 2000: normwise floor 5e-5) its error against the same
//   quotient evaluated in long double stays within its bound, and the bound is 1e-4 of the floor;
// - the structured Rayleigh-Ritz step unmixes a stiff chain's modes (and is then stationary).
#include "solvers/fe/fe_rayleigh_quotient.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "catena/statics/problem_builders.hpp"
#include "catena/statics/seabed_statics.hpp"
#include "solvers/fe/fe_eigen.hpp"
#include "solvers/fe/fe_line_mesh.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

internal::FeChain chain_of(const Problem& problem, int elements) {
  const StaticSolution statics = solve_statics(problem);
  return internal::solve_chain_statics(problem, statics, elements, problem.cable.axial_stiffness_n);
}

double assembled_quotient(const internal::FeMatrices& matrices, const Vector& phi) {
  return phi.dot(matrices.stiffness * phi) / phi.dot(matrices.mass * phi);
}

TEST(FeRayleighQuotient, EqualsTheAssembledQuotient) {
  const Problem grounded = testing::forty_percent_grounded_chain(0.1, 3e6);
  const StaticSolution seabed = solve_seabed_statics(grounded);
  const internal::FeChain with_contact = internal::solve_chain_statics(
      grounded, seabed, internal::make_line_mesh(grounded, seabed, 60),
      grounded.cable.axial_stiffness_n);
  ASSERT_GT(with_contact.grounded_elements, 0);
  for (const internal::FeChain& chain :
       {chain_of(make_taut_inclined_problem(0.1, 30.0, 50.0, 0.6), 40), with_contact}) {
    for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
      const internal::FeMatrices matrices = internal::assemble(plane, chain);
      const Vector phi = Vector::Random(matrices.stiffness.rows());
      const internal::RayleighQuotient q =
          internal::element_rayleigh_quotient(chain, plane, phi, matrices.mass);
      const double expected = assembled_quotient(matrices, phi);
      EXPECT_NEAR(q.value, expected, 1e-12 * expected) << to_string(plane);
      EXPECT_GT(q.relative_rounding, 0.0);
    }
  }
}

// The same quotient with the differences and sums in long double: the double evaluation's
// rounding shows against it.
double long_double_quotient(const internal::FeChain& chain,
                            const Vector& phi,
                            const internal::FeMatrices& matrices) {
  using Real = long double;
  auto node = [&](int i, int k) -> Real {
    return (i <= 0 || i >= chain.elements) ? 0.0L : static_cast<Real>(phi[2 * (i - 1) + k]);
  };
  Real energy = 0.0L;
  for (int j = 0; j < chain.elements; ++j) {
    const Real dx = node(j + 1, 0) - node(j, 0), dz = node(j + 1, 1) - node(j, 1);
    const Vec2& t = chain.direction[static_cast<std::size_t>(j)];
    const Real stretch = t.x() * dx + t.y() * dz, turn = t.x() * dz - t.y() * dx;
    energy += static_cast<Real>(chain.axial_stiffness_n[j] / chain.element_length_m[j]) * stretch *
                  stretch +
              static_cast<Real>(chain.tension_n[j] / chain.stretched_length_m[j]) * turn * turn;
  }
  Real kinetic = 0.0L;
  for (int k = 0; k < matrices.mass.outerSize(); ++k)
    for (internal::SparseMatrix::InnerIterator it(matrices.mass, k); it; ++it)
      kinetic += static_cast<Real>(phi[it.row()]) * it.value() * phi[it.col()];
  return static_cast<double>(energy / kinetic);
}

TEST(FeRayleighQuotient, BoundsItsRoundingOnAStiffChainFarBelowTheNormwiseFloor) {
  const Problem problem = make_taut_inclined_problem(1e-3, 0.0, 1.0, 1.0);  // EA/T0 = 1e6
  const int N = 2000;
  const internal::FeChain chain = chain_of(problem, N);
  const internal::FeMatrices matrices = internal::assemble(Plane::InPlane, chain);
  const internal::FeEigenSolution eigen = internal::solve_lowest_modes(matrices, 4, 1e-13, 1000);
  ASSERT_EQ(eigen.termination, Termination::Converged) << eigen.message;
  const double stiffness_ratio = problem.cable.axial_stiffness_n / chain.horizontal_force_n;
  ASSERT_GT(stiffness_ratio, 5e5);
  for (int n = 1; n <= 4; ++n) {
    const Vector phi = eigen.eigenvectors.col(n - 1);
    const internal::RayleighQuotient q =
        internal::element_rayleigh_quotient(chain, Plane::InPlane, phi, matrices.mass);
    const double reference = long_double_quotient(chain, phi, matrices);
    const double normwise = 0.5 * std::numeric_limits<double>::epsilon() * stiffness_ratio * N * N /
                            (M_PI * M_PI * n * n);
    EXPECT_LE(std::abs(q.value - reference), q.relative_rounding * reference) << n;
    EXPECT_LT(q.relative_rounding, 1e-4 * normwise) << n;
    // The quotient of the converged vector is the solver's eigenvalue to well within the floor.
    EXPECT_NEAR(q.value, eigen.eigenvalues[n - 1], normwise * eigen.eigenvalues[n - 1]) << n;
  }
}

// The structured Rayleigh-Ritz step removes the mixing a normwise projection leaves between
// neighbouring modes of a stiff chain: stress-eps at eps = 1e-4 (normwise floor 7e-3 on N = 800).
// How much the solver's own vectors are mixed is a matter of rounding (above 1e-8 relative in the
// first quotients when compiled for SSE2, 7e-9 with AVX2 and FMA, against bounds of 1.5-4e-9), so
// the test mixes converged Ritz vectors by a known rotation and asserts that one structured step
// takes the quotients back to the unmixed ones within their bounds, and that it is then
// stationary.
TEST(FeRayleighQuotient, StructuredRitzUnmixesTheModesOfAStiffChain) {
  const Problem problem = make_taut_inclined_problem(1e-4, 30.0, 10.0, 0.8);
  const internal::FeChain chain = chain_of(problem, 800);
  const internal::FeMatrices matrices = internal::assemble(Plane::InPlane, chain);
  const internal::FeEigenSolution eigen = internal::solve_lowest_modes(matrices, 4, 1e-13, 1000);
  ASSERT_EQ(eigen.termination, Termination::Converged) << eigen.message;
  Eigen::MatrixXd unmixed = eigen.eigenvectors;
  ASSERT_TRUE(internal::element_rayleigh_ritz(chain, Plane::InPlane, unmixed, matrices.mass));
  // Rotate modes 1 and 2, and 3 and 4, into each other by 1e-3 rad: each quotient moves by 1e-6
  // of the gap to its neighbour (0.5-1.2e-6 relative), far above the quotients' bounds.
  const double angle = 1e-3, c = std::cos(angle), s = std::sin(angle);
  Eigen::MatrixXd mixed = unmixed;
  for (int first : {0, 2}) {
    mixed.col(first) = c * unmixed.col(first) + s * unmixed.col(first + 1);
    mixed.col(first + 1) = -s * unmixed.col(first) + c * unmixed.col(first + 1);
  }
  Eigen::MatrixXd ritz = mixed;
  ASSERT_TRUE(internal::element_rayleigh_ritz(chain, Plane::InPlane, ritz, matrices.mass));
  Eigen::MatrixXd again = ritz;
  ASSERT_TRUE(internal::element_rayleigh_ritz(chain, Plane::InPlane, again, matrices.mass));
  double moved = 0.0, trace_before = 0.0, trace_after = 0.0;
  auto quotient = [&](const Eigen::MatrixXd& vectors, int i) {
    return internal::element_rayleigh_quotient(chain, Plane::InPlane, vectors.col(i),
                                               matrices.mass);
  };
  for (int i = 0; i < 4; ++i) {
    const auto reference = quotient(unmixed, i), before = quotient(mixed, i);
    const auto after = quotient(ritz, i), second = quotient(again, i);
    EXPECT_NEAR(after.value, reference.value, 2.0 * reference.relative_rounding * reference.value)
        << i;
    EXPECT_NEAR(second.value, after.value, 2.0 * after.relative_rounding * after.value) << i;
    moved = std::max(moved, std::abs(before.value - after.value) / after.value);
    trace_before += before.value;
    trace_after += after.value;
  }
  EXPECT_GT(moved, 1e-6);  // the mixing the step removed
  // A rotation within the span: the quotients' sum (the projected trace) stays.
  EXPECT_NEAR(trace_after, trace_before, 1e-9 * trace_before);
}

}  // namespace
}  // namespace catena
