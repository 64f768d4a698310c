// Tests of what the analytic solvers share (src/solvers/internal/taut_cable_theory.cpp): the
// static strain, the WKB out-of-plane modes (on a uniform string they are exact), and the door
// to eq. (21) and the first axial mode.
#include "solvers/internal/taut_cable_theory.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "catena/statics/problem_builders.hpp"
#include "catena/solvers/asymptotic_solver.hpp"
#include "solvers/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena::internal {
namespace {

using catena::testing::relative_error;

catena::testing::SolvedProblem taut(double eps = 0.18, double phi_deg = 23.46, double lambda2 = 38.0) {
  return catena::testing::prepare(make_taut_inclined_problem(eps, phi_deg, lambda2, 1.0));
}

TEST(TautCableTheory, StaticStrainIsT0OverEA) {
  const auto s = taut();
  EXPECT_DOUBLE_EQ(static_strain(s.problem, s.groups), s.groups.t0_n / s.problem.cable.axial_stiffness_n);
  Problem inextensible = s.problem;
  inextensible.cable.axial_stiffness_n = kInfinity;
  ASSERT_TRUE(inextensible.cable.is_inextensible());
  EXPECT_EQ(static_strain(inextensible, s.groups), 0.0);
}

TEST(TautCableTheory, WkbModesAreHarmonicsOfOneTravelTime) {
  // omega_n = n pi / tau: every frequency a multiple of the first; the shapes vanish at both
  // ends (sin(n pi) = 0 up to the quadrature, ~1e-15), are normalised to max |v| = 1, and carry
  // no first-order tension.
  const auto s = taut();
  SolveRequest request = catena::testing::modes_request(0, 4);
  request.shapes = true;
  request.tension = true;
  const double M = s.problem.cable.normal_mass_kg_per_m();
  const ModalResult result = wkb_outofplane_modes(s.statics, s.groups, request, M, 0.01, 4, "demo");
  ASSERT_EQ(result.modes.size(), 4u);
  EXPECT_EQ(result.summary.termination, Termination::Converged);
  EXPECT_EQ(result.summary.solver, "demo");
  EXPECT_EQ(result.plane, Plane::OutOfPlane);
  const std::vector<double> omegas = wkb_outofplane_omegas(s.statics, 4, 4);
  for (std::size_t i = 0; i < 4; ++i) {
    const Mode& mode = result.modes[i];
    EXPECT_EQ(mode.omega_rad_s, omegas[i]);
    EXPECT_LE(relative_error(mode.omega_rad_s, (i + 1) * result.modes[0].omega_rad_s), 1e-14);
    EXPECT_EQ(mode.relative_error_estimate, 0.01);
    const Index last = mode.v.size() - 1;
    EXPECT_LE(std::abs(mode.v[0]) + std::abs(mode.v[last]), 1e-12);
    EXPECT_DOUBLE_EQ(mode.v.cwiseAbs().maxCoeff(), 1.0);
    EXPECT_EQ(mode.tension_n.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_GT(mode.modal_mass_kg, 0.0);
  }
}

TEST(TautCableTheory, WkbFrequenciesWithoutShapesCarryNoShapes) {
  const auto s = taut();
  const ModalResult result = wkb_outofplane_modes(s.statics, s.groups, catena::testing::modes_request(0, 2),
                                                  s.problem.cable.normal_mass_kg_per_m(), 0.01, 4, "demo");
  ASSERT_EQ(result.modes.size(), 2u);
  EXPECT_EQ(result.modes[0].v.size(), 0);
  EXPECT_EQ(result.modes[0].s_m.size(), 0);
}

TEST(TautCableTheory, Eq21RootsForAHorizontalChordIncludeIrvinesAntisymmetricModes) {
  // phi = 0: eq. (21) is Irvine's; sin(kL/2) = 0 gives the antisymmetric roots kL = 2 n pi.
  const std::vector<double> roots = eq21_root_k_ls(4, 0.1, 0.0, 30.0);
  ASSERT_EQ(roots.size(), 4u);
  int antisymmetric = 0;
  for (double kl : roots) antisymmetric += std::abs(kl / (2.0 * kPi) - std::round(kl / (2.0 * kPi))) < 1e-14;
  EXPECT_EQ(antisymmetric, 2);
  EXPECT_EQ(roots, grinfogel_eq21_roots(4, 0.1, 0.0, 30.0));
}

TEST(TautCableTheory, FirstAxialModeIsTheBarMode) {
  // pi lambda / (eps cos(phi) sqrt(h)); none for an inextensible cable.
  const double eps = 0.2, phi = 0.3, lambda2 = 50.0, h = 0.8;
  EXPECT_LE(relative_error(first_axial_mode_k_l(eps, phi, lambda2, h),
                           kPi * std::sqrt(lambda2 / h) / (eps * std::cos(phi))),
            1e-15);
  EXPECT_TRUE(std::isinf(first_axial_mode_k_l(eps, phi, kInfinity, h)));
}

}  // namespace
}  // namespace catena::internal
