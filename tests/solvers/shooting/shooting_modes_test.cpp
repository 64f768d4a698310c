// SPDX-License-Identifier: MIT
// Tests of mode construction (src/solvers/shooting/shooting_modes): clustering of close roots,
// and modes with shapes from the null vector of Phi(L) on a uniform string, whose shapes are
// exact sines.
#include "solvers/shooting/shooting_modes.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/core/types.hpp"
#include "shooting_test_strings.hpp"

namespace catena::internal {
namespace {

Root root_at(double omega, int multiplicity = 1) {
  Root root;
  root.omega = omega;
  root.multiplicity = multiplicity;
  root.relative_error = 1e-11 * omega;
  root.residual = 1e-12;
  return root;
}

TEST(ShootingModes, ClustersJoinOnlyNeighboursCloserThanTheMergeDistance) {
  const std::vector<std::vector<Root>> clusters =
      cluster_roots({root_at(1.0), root_at(1.0 + 1e-8), root_at(2.0), root_at(3.0)}, 1e-7);
  ASSERT_EQ(clusters.size(), 3u);
  EXPECT_EQ(clusters[0].size(), 2u);
  EXPECT_EQ(clusters[1].size(), 1u);
  EXPECT_EQ(clusters[2][0].omega, 3.0);
}

IntegratorSettings tight() {
  IntegratorSettings settings;
  settings.relative_tolerance = 1e-12;
  settings.absolute_tolerance = 1e-14;
  return settings;
}

// The builder's context: a uniform cable (its modal mass from the coefficients' densities),
// default groups and the given request.
SolveContext context_for(const SolveRequest& request) {
  static const Problem problem;
  static const StaticSolution statics;
  static const DimensionlessGroups groups;
  return SolveContext{problem, statics, groups, request};
}

// T = 1 N, L = 1 m, EA = 4 N: transverse modes omega_n = n pi / sqrt(1 + e), e = 0.25.
const ShootingCoefficients kString = testing::horizontal_string(1.0, 1.0, 4.0);
double string_mode(int n) { return n * kPi / std::sqrt(1.25); }

TEST(ShootingModes, OutOfPlaneShapesAreNormalisedSinesWithTheirModalMass) {
  ShootingIntegrator integrator(Plane::OutOfPlane, kString, tight());
  SolveRequest request;
  request.shapes = true;
  request.tension = true;
  const SolveContext context = context_for(request);
  ShootingModeBuilder builder(integrator, kString, context, Plane::OutOfPlane, false);
  std::vector<Mode> modes;
  for (int n = 1; n <= 3; ++n) builder.add_cluster({root_at(string_mode(n))}, 3, modes);
  ASSERT_EQ(modes.size(), 3u);
  for (const Mode& mode : modes) {
    const int n = mode.index;
    EXPECT_EQ(mode.omega_rad_s, string_mode(n));
    ASSERT_EQ(mode.v.size(), 101);
    // The sign is fixed at the first station of largest |v|; the peaks of sin(n pi s) are equal to
    // rounding for n >= 2, so either sign may come out.
    const double sign = mode.v[1] > 0.0 ? 1.0 : -1.0;
    for (Index j = 0; j < mode.v.size(); ++j) {
      EXPECT_NEAR(mode.v[j], sign * std::sin(n * kPi * mode.s_m[j]), 1e-8) << n << " " << j;
    }
    EXPECT_NEAR(mode.modal_mass_kg, 0.5, 1e-8) << n;
    EXPECT_EQ(mode.tension_n, Vector::Zero(101));
  }
  EXPECT_DOUBLE_EQ(builder.max_error(), 1e-11 * string_mode(3));
  EXPECT_DOUBLE_EQ(builder.max_residual(), 1e-12);
}

TEST(ShootingModes, AMultipleRootGivesThatManyModesUpToTheCount) {
  ShootingIntegrator integrator(Plane::OutOfPlane, kString, tight());
  SolveRequest request;  // frequencies only: no shape shot at all
  const SolveContext context = context_for(request);
  ShootingModeBuilder builder(integrator, kString, context, Plane::OutOfPlane, false);
  std::vector<Mode> modes;
  builder.add_cluster({root_at(2.0, 2), root_at(2.0 + 1e-12)}, 2, modes);
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_EQ(modes[0].index, 1);
  EXPECT_EQ(modes[1].index, 2);
  EXPECT_EQ(modes[1].omega_rad_s, 2.0);
  EXPECT_EQ(modes[0].v.size(), 0);
  EXPECT_EQ(integrator.total_steps(), 0);
}

TEST(ShootingModes, StraightInextensibleInPlaneModesAreStringModesInW) {
  // A vertical inextensible cable under constant tension 1 N: the in-plane modes are the
  // transverse string modes, w = sin(n pi s), u = 0 and no dynamic tension.
  ShootingCoefficients k = testing::horizontal_string(1.0, 1.0);
  k.H = 0.0;
  k.V_A = 1.0;
  ShootingIntegrator integrator(Plane::OutOfPlane, k, tight());
  SolveRequest request;
  request.shapes = true;
  request.tension = true;
  const SolveContext context = context_for(request);
  ShootingModeBuilder builder(integrator, k, context, Plane::InPlane, true);
  std::vector<Mode> modes;
  builder.add_cluster({root_at(2.0 * kPi)}, 1, modes);
  ASSERT_EQ(modes.size(), 1u);
  ASSERT_EQ(modes[0].w.size(), 101);
  for (Index j = 0; j < 101; ++j) {
    EXPECT_NEAR(modes[0].w[j], std::sin(2.0 * kPi * modes[0].s_m[j]), 1e-8) << j;
    EXPECT_EQ(modes[0].u[j], 0.0);
    EXPECT_EQ(modes[0].tension_n[j], 0.0);
  }
}

}  // namespace
}  // namespace catena::internal
