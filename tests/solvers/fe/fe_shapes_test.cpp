// SPDX-License-Identifier: MIT
// fe stations (src/solvers/fe/fe_shapes.cpp): nodal displacements with their imposed ends,
// element tension of a uniform stretch, and linear sampling (exact for a linear field).
#include "solvers/fe/fe_shapes.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "catena/statics/problem_builders.hpp"
#include "solvers/common/mode_tools.hpp"
#include "solvers/fe/fe_operators.hpp"

namespace catena {
namespace {

struct Bar {
  Problem problem;
  StaticSolution statics;
  internal::FeChain chain;
};

// A straight horizontal bar, L = 1 m, EA = 10 N, stretched to 1.1 m, 10 elements.
Bar straight_bar() {
  Problem problem;
  problem.cable.length_m = 1.0;
  problem.cable.weight_n_per_m = 1e-9;
  problem.cable.axial_stiffness_n = 10.0;
  problem.cable.mass_kg_per_m = 1.0;
  problem.supports.b_m = Vec2(1.1, 0.0);
  StaticSolution statics = solve_statics(problem);
  internal::FeChain chain =
      internal::solve_chain_statics(problem, statics, 10, problem.cable.axial_stiffness_n);
  return {problem, std::move(statics), std::move(chain)};
}

TEST(FeShapes, NodeDisplacementsCarryTheImposedEnds) {
  Vector free(2 * 3);
  free << 1, 2, 3, 4, 5, 6;
  const auto inplane =
      internal::node_displacements(Plane::InPlane, 4, free, Vec2(7, 8), Vec2(9, 10));
  ASSERT_EQ(inplane.size(), 5u);
  EXPECT_EQ(inplane[0], Vec2(7, 8));
  EXPECT_EQ(inplane[2], Vec2(3, 4));
  EXPECT_EQ(inplane[4], Vec2(9, 10));
  const auto outofplane = internal::node_displacements(Plane::OutOfPlane, 4, free.head(3));
  EXPECT_EQ(outofplane[0], Vec2::Zero());
  EXPECT_EQ(outofplane[3], Vec2(3, 0));
}

TEST(FeShapes, UniformStretchGivesUniformTensionAndExactLinearSampling) {
  const Bar bar = straight_bar();
  const int N = bar.chain.elements;
  // Axial displacement growing linearly with the node: D_i = (c i l0, 0), a uniform strain c.
  const double c = 1e-3, l0 = bar.chain.element_length_m[0];
  std::vector<Vec2> D;
  for (int i = 0; i <= N; ++i) D.emplace_back(c * i * l0, 0.0);
  const Vector tau = internal::element_tension(bar.chain, D);
  for (int j = 0; j < N; ++j) EXPECT_NEAR(tau[j], bar.problem.cable.axial_stiffness_n * c, 1e-12);
  const Vector stations = Vector::LinSpaced(7, 0.0, 1.0);
  const internal::FeSampled sampled =
      internal::sample_on_stations(Plane::InPlane, bar.chain, D, &tau, stations, bar.statics);
  for (Index p = 0; p < stations.size(); ++p) {
    EXPECT_NEAR(sampled.u[p], c * stations[p], 1e-12) << "s = " << stations[p];  // the tangent is x
    EXPECT_NEAR(sampled.w[p], 0.0, 1e-10);  // the normal tilts by the sag angle W0 L / T ~ 1e-9
    EXPECT_NEAR(sampled.tension[p], bar.problem.cable.axial_stiffness_n * c, 1e-12);
  }
}

TEST(FeShapes, ModeOnStationsIsNormalised) {
  const Bar bar = straight_bar();
  Vector eigenvector(bar.chain.elements - 1);
  for (Index i = 0; i < eigenvector.size(); ++i)
    eigenvector[i] = -3.0 * std::sin(kPi * (i + 1) / 10.0);
  const Mode mode = internal::mode_on_stations(Plane::OutOfPlane, bar.chain, eigenvector,
                                               Vector::LinSpaced(11, 0.0, 1.0), bar.statics, true);
  EXPECT_EQ(mode.normalised_by, "v");
  EXPECT_NEAR(mode.v.maxCoeff(), 1.0, 1e-12);   // the peak made positive and 1
  EXPECT_EQ(mode.tension_n, Vector::Zero(11));  // no first-order tension out of plane
}

// mode_on_stations reads the nodes next to each station from the eigenvector in place; the result
// must be the same as sampling the full copy of the nodes (node_displacements) with every
// element's tension (element_tension): the displacements bit for bit, the tension to a few units
// in the last place of its largest value (the compiler may fuse a multiply and an add in one
// path and not in the other when it targets FMA, cmake/instruction_set.cmake).
TEST(FeShapes, ModeOnStationsEqualsSamplingTheCopiedNodes) {
  const Problem problem = make_taut_inclined_problem(0.1, 30.0, 50.0, 0.6);
  const StaticSolution statics = solve_statics(problem);
  const internal::FeChain chain =
      internal::solve_chain_statics(problem, statics, 16, problem.cable.axial_stiffness_n);
  const Vector stations = Vector::LinSpaced(23, 0.0, problem.length_m());
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const Vector free =
        Vector::LinSpaced(internal::fe_unknowns(plane, 16), -1.0, 2.0).array().sin();
    const std::vector<Vec2> D = internal::node_displacements(plane, 16, free);
    const Vector tau = internal::element_tension(chain, D);
    const bool inplane = plane == Plane::InPlane;
    const internal::FeSampled copied =
        internal::sample_on_stations(plane, chain, D, inplane ? &tau : nullptr, stations, statics);
    Mode expected;
    expected.s_m = stations;
    if (inplane) {
      expected.u = copied.u;
      expected.w = copied.w;
      expected.tension_n = copied.tension;
      internal::normalise_inplane_mode(expected);
    } else {
      expected.v = copied.v;
      internal::normalise_outofplane_mode(expected);
    }
    const Mode mode = internal::mode_on_stations(plane, chain, free, stations, statics, true);
    EXPECT_EQ(mode.u, expected.u);
    EXPECT_EQ(mode.w, expected.w);
    EXPECT_EQ(mode.v, expected.v);
    if (inplane) {
      const double largest = expected.tension_n.cwiseAbs().maxCoeff();
      const double last_place = std::numeric_limits<double>::epsilon() * largest;
      EXPECT_LE((mode.tension_n - expected.tension_n).cwiseAbs().maxCoeff(), 4.0 * last_place);
    }
  }
}

}  // namespace
}  // namespace catena
