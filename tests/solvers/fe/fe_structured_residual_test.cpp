// SPDX-License-Identifier: MIT
// The in-plane forced residual from the chain's element data (src/solvers/fe/
// fe_structured_residual.hpp): it is the assembled residual f - (K - w^2 M) x up to the rounding of
// the assembled entries, on a cable and on a line resting on the seabed (tests/solvers/
// fe_seabed_test.cpp), and on a penalised chain one refinement step with it removes that rounding.
#include "solvers/fe/fe_structured_residual.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "solvers/fe/fe_banded_ldlt.hpp"

namespace catena::testing {

// f - (K - w^2 M) x from the assembled matrices (f the ends' coupling), and the scale of the
// rounding of its element part, eps max(EA/l0) (|x| + |ends|).
struct AssembledResidual {
  Vector residual;
  double rounding_scale = 0.0;
};

AssembledResidual assembled_residual(const internal::FeChain& chain,
                                     const internal::FeMatrices& matrices,
                                     double omega,
                                     const Vector& x,
                                     const Vec2& end_a,
                                     const Vec2& end_b) {
  Vector ends(4);
  ends << end_a, end_b;
  AssembledResidual out;
  out.residual = -(matrices.boundary_coupling * ends) -
                 (matrices.stiffness * x - omega * omega * (matrices.mass * x));
  const double stiffest =
      (chain.axial_stiffness_n.array() / chain.element_length_m.array()).maxCoeff();
  out.rounding_scale = std::numeric_limits<double>::epsilon() * stiffest *
                       (x.cwiseAbs().maxCoeff() + ends.cwiseAbs().maxCoeff());
  return out;
}

// A reproducible vector of size n with entries in [-1, 1].
Vector pseudo_random(Eigen::Index n) {
  Vector x(n);
  for (Eigen::Index i = 0; i < n; ++i) x[i] = std::sin(1.7 * static_cast<double>(i) + 0.3);
  return x;
}

TEST(FeStructuredResidual, IsTheAssembledResidualUpToTheRoundingOfTheEntries) {
  const SolvedProblem cable = prepare(make_taut_inclined_problem(0.1, 20.0, 10.0, 1.0));
  const internal::FeChain chain = internal::solve_chain_statics(
      cable.problem, cable.statics, 40, cable.problem.cable.axial_stiffness_n);
  const internal::FeMatrices matrices = internal::assemble(Plane::InPlane, chain);
  const Vector x = 1e-3 * pseudo_random(matrices.stiffness.rows());
  const Vec2 end_a(0.0, 0.0), end_b(2e-3, -1e-3);
  const double omega = 3.0 * cable.groups.taut_frequency_scale_rad_s;
  const AssembledResidual assembled = assembled_residual(chain, matrices, omega, x, end_a, end_b);
  const Vector structured =
      internal::inplane_structured_residual(chain, matrices, omega, x, end_a, end_b);
  ASSERT_EQ(structured.size(), x.size());
  EXPECT_LE((structured - assembled.residual).cwiseAbs().maxCoeff(),
            100.0 * assembled.rounding_scale);
  // Not trivially small: the residual of an arbitrary x is of the size of the forces.
  EXPECT_GT(structured.cwiseAbs().maxCoeff(), 1e6 * assembled.rounding_scale);
}

TEST(FeStructuredResidual, RefinementWithItConvergesOnAPenalisedChain) {
  // Gale's inextensible catenary at kappa = 1e-6 (a / b ~ 1e6), forced near a resonance. The
  // residual itself cannot fall below eps a |x| (x is stored in double); what the refinement
  // changes is x, the solution of the unrounded chain instead of the rounded one: the first step
  // moves it, the second far less.
  const SolvedProblem gale = prepare(make_gale_sag_problem(0.0, 0.7));
  const double H = gale.statics.horizontal_force_n();
  const internal::FeChain chain =
      internal::solve_chain_statics(gale.problem, gale.statics, 400, H / 1e-6);
  const internal::FeMatrices matrices = internal::assemble(Plane::InPlane, chain);
  const double omega = 1.32 * gale.groups.gale_frequency_scale_rad_s;
  const Vec2 end_a(0.0, 0.0), end_b = 0.01 * H / gale.problem.cable.weight_n_per_m *
                                      gale.statics.tangent(gale.problem.cable.length_m);
  const internal::SparseMatrix dynamic = matrices.stiffness - omega * omega * matrices.mass;
  internal::BandedLdlt factor;
  ASSERT_TRUE(factor.factorize(dynamic));
  Vector ends(4);
  ends << end_a, end_b;
  Vector x = -(matrices.boundary_coupling * ends);
  factor.solve_in_place(x.data());
  auto step = [&] {
    Vector correction =
        internal::inplane_structured_residual(chain, matrices, omega, x, end_a, end_b);
    factor.solve_in_place(correction.data());
    x += correction;
    return correction.norm();
  };
  const double first = step(), second = step();
  EXPECT_GT(first, 1e-9 * x.norm())
      << "the rounded chain's solution differs from the unrounded one's";
  EXPECT_LT(second, 1e-2 * first) << first << " then " << second;
}

}  // namespace catena::testing
