// SPDX-License-Identifier: MIT
// The forced response on a general line (docs/explanation/methods/fe.md, "Lines";
// docs/explanation/methods/shooting.md, "General lines"), by fe and by shooting:
// - a weightless taut line of two segments with different mass densities, driven out of plane at
//   end b: the exact response is a sine on each segment, matched in v and T v' at the joint
//   (both solvers against it);
// - a sagging line with a heavy point weight (a kink in the static line), driven in plane at either
//   end away from resonance: fe and shooting agree on the dynamic tension and displacements, within
//   fe's own error estimate.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catena/solvers/fe_solver.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using Solved = catena::testing::SolvedProblem;

ShootingSolverOptions tight_shooting() {
  ShootingSolverOptions options;
  options.relative_tolerance = 1e-12;
  return options;
}

SolveRequest forced_request(CableEnd end, ForcingDirection direction, std::vector<double> omegas) {
  SolveRequest request = catena::testing::modes_request(0, 0);
  ForcedRequest forced;
  forced.end = end;
  forced.direction = direction;
  forced.amplitude_m = 0.1;
  forced.omegas_rad_s = std::move(omegas);
  request.forced = forced;
  return request;
}

double max_abs(const Vector& x) { return x.cwiseAbs().maxCoeff(); }
double max_abs_difference(const Vector& a, const Vector& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

// Two weightless segments (40 m of 12 kg/m, 60 m of 2.5 kg/m, normal mass with added mass), EA =
// 1e7 N, stretched from 100 m to 100.1 m: T = 1e4 N. Out-of-plane natural frequencies 1.26, 2.84,
// 3.87, 5.49 rad/s.
Problem two_density_line() {
  Problem p;
  p.line.segments = {{40.0, 0.0, 1e7, 10.0, 2.0}, {60.0, 0.0, 1e7, 2.0, 0.5}};
  p.supports.b_m = Vec2(100.1, 0.0);
  return p;
}

// The exact out-of-plane response to v(L) = d, v(0) = 0: (T / (1 + e)) v'' + w^2 M v = 0 on each
// segment, v and v' continuous at the joint (same T and stretch on both sides).
Vector exact_two_density_response(const Vector& s, double omega, double d) {
  const double T = 1e4, stretch = 1.0 + T / 1e7, L1 = 40.0, L = 100.0;
  const double k1 = omega * std::sqrt(12.0 * stretch / T),
               k2 = omega * std::sqrt(2.5 * stretch / T);
  auto shape = [&](double x) {
    if (x <= L1) return std::sin(k1 * x);
    return std::sin(k1 * L1) * std::cos(k2 * (x - L1)) +
           (k1 / k2) * std::cos(k1 * L1) * std::sin(k2 * (x - L1));
  };
  Vector v(s.size());
  for (Index j = 0; j < s.size(); ++j) v[j] = d * shape(s[j]) / shape(L);
  return v;
}

TEST(LineForced, TwoDensityStringMatchesTheExactResponseInBothSolvers) {
  const Problem p = two_density_line();
  const SolveRequest request =
      forced_request(CableEnd::B, ForcingDirection::OutOfPlane, {0.7, 2.0, 4.6});
  const Solved fe =
      catena::testing::solve_problem(solve_fe, p, request, FeSolverOptions{.elements = 1000});
  const Solved shooting =
      catena::testing::solve_problem(solve_shooting, p, request, tight_shooting());
  ASSERT_NEAR(shooting.statics.horizontal_force_n(), 1e4, 1e-5);
  for (const Solved* solved : {&fe, &shooting}) {
    ASSERT_EQ(solved->output.forced.size(), 3u);
    for (const ForcedResponse& response : solved->output.forced) {
      ASSERT_TRUE(response.diagnostic.empty()) << response.diagnostic;
      const Vector exact = exact_two_density_response(response.s_m, response.omega_rad_s, 0.1);
      const double error = max_abs_difference(response.v, exact) / max_abs(exact);
      EXPECT_LE(error, solved == &fe ? 1e-8 : 1e-9)
          << (solved == &fe ? "fe" : "shooting") << " at " << response.omega_rad_s << " rad/s";
    }
  }
}

// A sagging line of two segments with a 5 kN point weight at s = 20 m (a kink in the static line).
Problem kinked_line() {
  Problem p;
  p.line.segments = {{40.0, 100.0, 1e8, 10.0, 10.0}, {60.0, 150.0, 5e7, 6.0, 4.0}};
  PointAttachment point;
  point.s_m = 20.0;
  point.mass_kg = 500.0;
  point.weight_n = 5000.0;
  p.line.points = {point};
  p.supports.b_m = Vec2(80.0, 30.0);
  return p;
}

TEST(LineForced, FeAndShootingAgreeInPlaneAwayFromResonance) {
  // The line's lowest in-plane frequencies are 1.13, 2.05 and 3.19 rad/s; these lie below and
  // between.
  for (CableEnd end : {CableEnd::A, CableEnd::B}) {
    const SolveRequest request = forced_request(end, ForcingDirection::Normal, {0.5, 1.6, 2.6});
    const Solved fe = catena::testing::solve_problem(solve_fe, kinked_line(), request,
                                                     FeSolverOptions{.elements = 1000});
    const Solved shooting =
        catena::testing::solve_problem(solve_shooting, kinked_line(), request, tight_shooting());
    ASSERT_EQ(fe.output.forced.size(), 3u);
    ASSERT_EQ(shooting.output.forced.size(), 3u);
    for (std::size_t f = 0; f < 3; ++f) {
      const ForcedResponse& a = fe.output.forced[f];
      const ForcedResponse& b = shooting.output.forced[f];
      ASSERT_TRUE(a.diagnostic.empty() && b.diagnostic.empty()) << a.diagnostic << b.diagnostic;
      EXPECT_FALSE(a.near_resonance || b.near_resonance);
      const double tension = max_abs_difference(a.tension_n, b.tension_n) / max_abs(b.tension_n);
      const double scale = std::max(max_abs(b.u), max_abs(b.w));
      const double displacement =
          std::max(max_abs_difference(a.u, b.u), max_abs_difference(a.w, b.w)) / scale;
      EXPECT_LE(tension, a.relative_error_estimate) << "at " << a.omega_rad_s << " rad/s";
      EXPECT_LE(tension, 1e-7) << "at " << a.omega_rad_s << " rad/s";
      EXPECT_LE(displacement, 1e-7) << "at " << a.omega_rad_s << " rad/s";
    }
  }
}

}  // namespace
}  // namespace catena
