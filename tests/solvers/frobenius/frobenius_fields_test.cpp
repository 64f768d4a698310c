// SPDX-License-Identifier: MIT
// Tests of the frobenius solver's fields: the null vector meets the boundary conditions, the
// fields of a mode vanish at both ends, V = C^2 DU, and the out-of-plane mode n has n - 1
// interior nodes (the Sturm check of the count).
#include "solvers/frobenius/frobenius_fields.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solvers/frobenius/frobenius_root_scan.hpp"
#include "solvers/frobenius/frobenius_test_support.hpp"

namespace catena::internal {
namespace {

using catena::testing::frobenius_plane;

std::vector<double> sigmas_between(double sigma1, double sigma2, int points) {
  std::vector<double> out;
  for (int i = 0; i < points; ++i) out.push_back(sigma1 + (sigma2 - sigma1) * i / (points - 1));
  return out;
}

TEST(FrobeniusFieldsTest, ModeFieldsVanishAtBothEnds) {
  const PlaneSetup setup = frobenius_plane(true, -0.6, 1.2);
  const PlaneRoots found = find_frequencies(setup, 3, RootSettings{});
  ASSERT_EQ(found.roots.size(), 3u);
  for (const FoundRoot& root : found.roots) {
    const auto values =
        mode_fields(Precision::LongDouble, setup, root.omega, sigmas_between(-0.6, 1.2, 101), true);
    ASSERT_EQ(values.size(), 101u);
    double largest = 0.0;
    for (const auto& f : values) largest = std::max({largest, std::abs(f.u), std::abs(f.v)});
    ASSERT_GT(largest, 0.0);
    for (const FieldValues* end : {&values.front(), &values.back()}) {
      EXPECT_LT(std::abs(end->u), 1e-9 * largest) << root.omega;
      EXPECT_LT(std::abs(end->v), 1e-9 * largest) << root.omega;
    }
  }
}

TEST(FrobeniusFieldsTest, NormalDisplacementIsCSquaredTimesTheSlopeOfTheTangential) {
  // V = C^2 dU/dsigma (inextensibility), checked by central differences of U.
  const PlaneSetup setup = frobenius_plane(true, -0.5, 0.9);
  const PlaneRoots found = find_frequencies(setup, 1, RootSettings{});
  ASSERT_EQ(found.roots.size(), 1u);
  const double h = 1e-5;
  const std::vector<double> sigmas{0.2 - h, 0.2, 0.2 + h};
  const auto values = mode_fields(Precision::Double, setup, found.roots[0].omega, sigmas, false);
  const double du = (values[2].u - values[0].u) / (2.0 * h);
  EXPECT_NEAR(values[1].v, (1.0 + 0.04) * du, 1e-7 * std::abs(values[1].v) + 1e-12);
}

TEST(FrobeniusFieldsTest, InteriorSignChangesLeaveOutTheEndStations) {
  Vector v(6);
  v << -1e-17, 1.0, 2.0, -1.0, 3.0, 1e-17;
  EXPECT_EQ(interior_sign_changes(v), 2);
  Vector flat(4);
  flat << 0.0, 1.0, 1.0, -0.0;
  EXPECT_EQ(interior_sign_changes(flat), 0);
}

TEST(FrobeniusFieldsTest, OutOfPlaneModeNHasNMinusOneInteriorNodesAndIsNormalised) {
  const PlaneSetup setup = frobenius_plane(false, -0.6, 1.2);
  const PlaneRoots found = find_frequencies(setup, 3, RootSettings{});
  ASSERT_EQ(found.roots.size(), 3u);
  FieldStations stations;
  stations.s_m = Vector::LinSpaced(201, 0.0, 1.0);
  stations.sigma = sigmas_between(-0.6, 1.2, 201);
  const ModeFieldRequest request{true, false, &stations, &stations};
  for (std::size_t n = 0; n < 3; ++n) {
    Mode mode;
    mode.index = static_cast<int>(n) + 1;
    EXPECT_EQ(add_mode_fields(mode, setup, found.roots[n].omega, Precision::Double, request,
                              CableUnits{}),
              static_cast<int>(n));
    ASSERT_EQ(mode.v.size(), 201);
    EXPECT_NEAR(mode.v.cwiseAbs().maxCoeff(), 1.0, 1e-12);
    EXPECT_GT(mode.modal_mass_kg, 0.0);
  }
}

TEST(FrobeniusFieldsTest, WithoutShapesOnlyTheMaximumTensionIsKept) {
  const PlaneSetup setup = frobenius_plane(true, -0.6, 1.2);
  const PlaneRoots found = find_frequencies(setup, 1, RootSettings{});
  ASSERT_EQ(found.roots.size(), 1u);
  FieldStations dense;
  dense.s_m = Vector::LinSpaced(101, 0.0, 1.0);
  dense.sigma = sigmas_between(-0.6, 1.2, 101);
  const ModeFieldRequest request{false, true, nullptr, &dense};
  Mode mode;
  mode.index = 1;
  EXPECT_EQ(
      add_mode_fields(mode, setup, found.roots[0].omega, Precision::Double, request, CableUnits{}),
      -1);
  EXPECT_EQ(mode.s_m.size(), 0);
  EXPECT_EQ(mode.tension_n.size(), 0);
  EXPECT_GT(mode.max_abs_tension_n, 0.0);
  EXPECT_EQ(mode.modal_mass_kg, -1.0);
}

}  // namespace
}  // namespace catena::internal
