// SPDX-License-Identifier: MIT
// Independent anchors of fe and shooting on general lines, in plane as well as out of plane
// (docs/explanation/physics.md, "General lines"). Each is a weightless taut line, straight along x,
// whose in-plane motion splits into an axial bar (stiffness EA, mass m + point mass + its
// tangential added mass) and a transverse string (stiffness S = T / (1 + e) per unstretched length,
// normal mass M); out of plane it is the same string. The exact frequency equations are solved here
// by bisection, independently of both solvers:
// - a point mass P at s = a (off centre) on a line of one section, fixed at both ends:
//     S k sin(k L) = w^2 P sin(k a) sin(k (L - a)), k = w / c, for the bar (S = EA, c^2 = EA / m)
//     and for the string (S = T / (1 + e), c^2 = S / M);
// - two segments of different EA (and mass): the same tension, different strains;
//     S1 k1 cos(k1 L1) sin(k2 L2) + S2 k2 sin(k1 L1) cos(k2 L2) = 0
//   for the two-part bar (S_i = EA_i) and the two-part string (S_i = T / (1 + e_i)).
// fe (N = 1000 with Richardson) and shooting (rtol 1e-12) are held to 1e-9 on the first 10 modes
// of each plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "catena/solvers/fe_solver.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::relative_error;
using catena::testing::roots_by_bisection;
using Solved = catena::testing::SolvedProblem;

constexpr int kModes = 10;
constexpr double kAnchorTolerance = 1e-9;  // measured: at most 1.3e-10 (both solvers)

// The lowest `count` of two families of frequencies, merged.
std::vector<double> merged(std::vector<double> a, const std::vector<double>& b, int count) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.resize(static_cast<std::size_t>(count));
  return a;
}

// Both solvers, 10 modes per plane, against the exact frequencies of each plane.
void expect_both_solvers_match(const Problem& p,
                               const std::vector<double>& inplane,
                               const std::vector<double>& outofplane) {
  ASSERT_EQ(inplane.size(), static_cast<std::size_t>(kModes));
  ASSERT_EQ(outofplane.size(), static_cast<std::size_t>(kModes));
  ShootingSolverOptions tight;
  tight.relative_tolerance = 1e-12;
  const SolveRequest request = catena::testing::modes_request(kModes, kModes);
  const Solved fe =
      catena::testing::solve_problem(solve_fe, p, request, FeSolverOptions{.elements = 1000});
  const Solved shooting = catena::testing::solve_problem(solve_shooting, p, request, tight);
  for (const Solved* solved : {&fe, &shooting}) {
    const char* name = solved == &fe ? "fe" : "shooting";
    ASSERT_EQ(solved->output.summary.termination, Termination::Converged)
        << name << ": " << solved->output.summary.full_report();
    for (const bool in_plane : {true, false}) {
      const ModalResult& result = in_plane ? *solved->output.inplane : *solved->output.outofplane;
      const std::vector<double>& exact = in_plane ? inplane : outofplane;
      ASSERT_EQ(result.modes.size(), exact.size());
      for (std::size_t i = 0; i < exact.size(); ++i) {
        EXPECT_LE(relative_error(result.modes[i].omega_rad_s, exact[i]), kAnchorTolerance)
            << name << (in_plane ? " in plane" : " out of plane") << " mode " << i + 1 << ": "
            << result.modes[i].omega_rad_s << " against " << exact[i];
      }
    }
  }
}

// Fixed-fixed wave equation S u'' + w^2 rho u = 0 on (0, L) with a point inertia P at a.
std::vector<double> point_mass_frequencies(
    double S, double rho, double L, double a, double P, double top) {
  const double c = std::sqrt(S / rho);
  auto equation = [&](double w) {
    const double k = w / c;
    return S * k * std::sin(k * L) - w * w * P * std::sin(k * a) * std::sin(k * (L - a));
  };
  return roots_by_bisection(equation, top, kModes);
}

TEST(LineAnchors, OffCentrePointMassOnATautLineInBothPlanes) {
  // 100 m of 4 kg/m (normal added mass 1 kg/m), EA = 1e7 N, stretched 4 % (T = 4e5 N; the axial
  // mode 5 in plane is axial); a 150 kg point with 30 kg isotropic added mass at 30 m.
  const double L = 100.0, a = 30.0, EA = 1e7, strain = 0.04, m = 4.0, M = 5.0, P = 180.0;
  Problem p;
  p.line.segments = {{L, 0.0, EA, m, M - m}};
  PointAttachment point;
  point.s_m = a;
  point.mass_kg = 150.0;
  point.added_mass_kg = 30.0;
  p.line.points = {point};
  p.supports.b_m = Vec2(L * (1.0 + strain), 0.0);
  const double T = EA * strain, S = T / (1.0 + strain);
  const double string_top = 12.0 * kPi * std::sqrt(S / M) / L;
  const std::vector<double> string = point_mass_frequencies(S, M, L, a, P, string_top);
  const std::vector<double> bar =
      point_mass_frequencies(EA, m, L, a, P, 12.0 * kPi * std::sqrt(EA / m) / L);
  expect_both_solvers_match(p, merged(string, bar, kModes), string);
}

// Fixed-fixed two-part wave equation: S_i u'' + w^2 rho_i u = 0 on each part, S u' continuous.
std::vector<double> two_part_frequencies(
    double S1, double rho1, double L1, double S2, double rho2, double L2, double top) {
  auto equation = [&](double w) {
    const double k1 = w * std::sqrt(rho1 / S1), k2 = w * std::sqrt(rho2 / S2);
    return S1 * k1 * std::cos(k1 * L1) * std::sin(k2 * L2) +
           S2 * k2 * std::sin(k1 * L1) * std::cos(k2 * L2);
  };
  return roots_by_bisection(equation, top, kModes);
}

TEST(LineAnchors, TwoSegmentsOfDifferentEAInBothPlanes) {
  // 40 m of EA = 2e7 N, 6 kg/m (M = 7) and 60 m of EA = 5e6 N, 3 kg/m (M = 3.5), stretched by
  // 5 m: T = 5 / (L1 / EA1 + L2 / EA2) = 3.57e5 N, strains T / EA_i of 1.8 % and 7.1 % (in plane,
  // mode 7 is axial).
  const double L1 = 40.0, L2 = 60.0, EA1 = 2e7, EA2 = 5e6, m1 = 6.0, m2 = 3.0, M1 = 7.0, M2 = 3.5;
  Problem p;
  p.line.segments = {{L1, 0.0, EA1, m1, M1 - m1}, {L2, 0.0, EA2, m2, M2 - m2}};
  p.supports.b_m = Vec2(L1 + L2 + 5.0, 0.0);
  const double T = 5.0 / (L1 / EA1 + L2 / EA2);
  const double S1 = T / (1.0 + T / EA1), S2 = T / (1.0 + T / EA2);
  // The n-th root is near n pi / (travel time L1 / c1 + L2 / c2): search up to the 12th.
  auto top = [&](double S1_, double rho1, double S2_, double rho2) {
    return 12.0 * kPi / (L1 * std::sqrt(rho1 / S1_) + L2 * std::sqrt(rho2 / S2_));
  };
  const std::vector<double> string =
      two_part_frequencies(S1, M1, L1, S2, M2, L2, top(S1, M1, S2, M2));
  const std::vector<double> bar =
      two_part_frequencies(EA1, m1, L1, EA2, m2, L2, top(EA1, m1, EA2, m2));
  expect_both_solvers_match(p, merged(string, bar, kModes), string);
}

}  // namespace
}  // namespace catena
