// SPDX-License-Identifier: MIT
// Mode shapes, dynamic tension, modal mass and forced response of the `shooting` solver, against
// exact results:
//  - straight, nearly weightless cable (weight 1e-9 N/m): transverse modes w = sin(n pi s/L) with
//    zero dynamic tension, axial modes u = sin(n pi s/L) with tau = EA u' (normalised by u);
//  - forced response of the same cable: u = d sin(k s)/sin(k L), tau = EA u' (tangential drive,
//    k = omega sqrt(m/EA)); w, v = d sin(k s)/sin(k L) (normal / out-of-plane drive,
//    k = omega sqrt(M (1+e)/T)); the mirror image when end a is driven; a resonance diagnostic;
//  - vertical inextensible cable (H = 0): string with tension T_A + W0 s, exact frequencies from
//    the Bessel cross product J0(z_A) Y0(z_B) - J0(z_B) Y0(z_A) = 0, z = 2 omega sqrt(M T)/W0,
//    in plane and out of plane alike;
//  - mass orthogonality of the modes of a sagging inextensible cable (Gale) with added mass;
//  - the forced response at omega = 0 equals the derivative of the shared statics with respect to
//    the position of the driven support (central finite difference of solve_statics), for a deep
//    inextensible catenary and an elastic mooring line, tangential and normal drives.
#include <gtest/gtest.h>

#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>

#include "catena/solvers/shooting_solver.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/mode_tools.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using testing::relative_error;

// rtol 1e-12: shapes interpolated by CVODE's dense output carry errors of that order relative to
// the mode amplitude; 1e-8 leaves room for the normalisation by a sampled maximum.
constexpr double kShapeTol = 1e-8;

Problem straight_cable(double tension_n, double ea_n, double length_m = 10.0) {
  Problem problem;
  problem.cable.length_m = length_m;
  problem.cable.weight_n_per_m = 1e-9;
  problem.cable.axial_stiffness_n = ea_n;
  problem.cable.mass_kg_per_m = 1.0;
  problem.supports.b_m = Vec2(length_m * (1.0 + tension_n / ea_n), 0.0);
  return problem;
}

SolverOutput run(const Problem& problem, const SolveRequest& request, double rtol = 1e-12) {
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  ShootingSolverOptions options;
  options.relative_tolerance = rtol;
  return solve_shooting(problem, statics, groups, request, options);
}

TEST(ShootingShapes, StraightCableModesHaveExactShapesAndTension) {
  const double EA = 1e4, L = 10.0;
  SolveRequest request;
  request.inplane_modes = 4;  // string 1, string 2, bar 1, string 3
  request.outofplane_modes = 2;
  request.shapes = true;
  request.tension = true;
  request.points = 201;
  const SolverOutput out = run(straight_cable(2000.0, EA), request);
  ASSERT_EQ(out.summary.termination, Termination::Converged) << out.summary.full_report();
  int string_index = 0, bar_index = 0;
  for (const Mode& mode : out.inplane->modes) {
    const bool axial = mode.normalised_by == "u";
    const int n = axial ? ++bar_index : ++string_index;
    const Vector& shape = axial ? mode.u : mode.w;
    const Vector& other = axial ? mode.w : mode.u;
    double max_shape_error = 0.0, max_tension_error = 0.0;
    // The shape is normalised to +1 at its first sampled maximum: align the sign of the exact
    // shape there
    // (ties within 1e-9 go to the first station, as in mode_tools).
    Index peak = 0;
    const double peak_value = shape.cwiseAbs().maxCoeff();
    while (std::abs(shape[peak]) < peak_value * (1.0 - 1e-9)) ++peak;
    const double sign = std::sin(n * kPi * mode.s_m[peak] / L) > 0.0 ? 1.0 : -1.0;
    for (Index j = 0; j < mode.s_m.size(); ++j) {
      const double s = mode.s_m[j];
      const double exact = sign * std::sin(n * kPi * s / L);
      max_shape_error = std::max(max_shape_error, std::abs(shape[j] - exact));
      const double exact_tension =
          axial ? sign * EA * n * kPi / L * std::cos(n * kPi * s / L) : 0.0;
      max_tension_error = std::max(max_tension_error, std::abs(mode.tension_n[j] - exact_tension));
      EXPECT_LT(std::abs(other[j]), kShapeTol) << "mode " << mode.index << " cross component";
    }
    EXPECT_LT(max_shape_error, kShapeTol)
        << "mode " << mode.index << (axial ? " (bar)" : " (string)");
    EXPECT_LT(max_tension_error, kShapeTol * EA) << "mode " << mode.index;
    // Modal mass of sin(n pi s/L): m L / 2.
    EXPECT_LT(relative_error(mode.modal_mass_kg, 0.5 * L), 1e-4) << "mode " << mode.index;
  }
  EXPECT_EQ(bar_index, 1);
  for (const Mode& mode : out.outofplane->modes) {
    for (Index j = 0; j < mode.s_m.size(); ++j) {
      EXPECT_NEAR(mode.v[j], std::sin(mode.index * kPi * mode.s_m[j] / L), kShapeTol);
    }
  }
}

TEST(ShootingShapes, ModesOfASaggingCableWithAddedMassAreMassOrthogonal) {
  // Trapezoid on 2001 stations: integration error ~ (L/2000)^2 relative.
  constexpr double kOrthogonalityTol = 1e-5;
  Problem problem = make_gale_sag_problem(0.5, 0.8);
  problem.cable.added_mass_kg_per_m = 0.7;
  SolveRequest request;
  request.inplane_modes = 5;
  request.outofplane_modes = 3;
  request.shapes = true;
  request.points = 2001;
  const SolverOutput out = run(problem, request, 1e-10);
  ASSERT_EQ(out.summary.termination, Termination::Converged) << out.summary.full_report();
  const double m = problem.cable.mass_kg_per_m, M = problem.cable.normal_mass_kg_per_m();
  const auto& modes = out.inplane->modes;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      const Vector density =
          m * modes[i].u.cwiseProduct(modes[j].u) + M * modes[i].w.cwiseProduct(modes[j].w);
      const double cross = internal::integrate_on_stations(modes[i].s_m, density);
      const double scale = std::sqrt(modes[i].modal_mass_kg * modes[j].modal_mass_kg);
      EXPECT_LT(std::abs(cross) / scale, kOrthogonalityTol) << "modes " << i + 1 << ", " << j + 1;
    }
  }
  const auto& oop = out.outofplane->modes;
  for (std::size_t i = 0; i < oop.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      const double cross =
          internal::integrate_on_stations(oop[i].s_m, M * oop[i].v.cwiseProduct(oop[j].v));
      EXPECT_LT(std::abs(cross) / std::sqrt(oop[i].modal_mass_kg * oop[j].modal_mass_kg),
                kOrthogonalityTol);
    }
  }
}

TEST(ShootingForced, StraightCableResponseIsExact) {
  const double EA = 1e4, L = 10.0, d = 0.01;
  const Problem problem = straight_cable(2000.0, EA);
  const StaticSolution statics = solve_statics(problem);
  const double T = statics.tension_n(0.5 * L);
  const double e = T / EA;
  for (ForcingDirection direction :
       {ForcingDirection::Tangential, ForcingDirection::Normal, ForcingDirection::OutOfPlane}) {
    for (CableEnd end : {CableEnd::B, CableEnd::A}) {
      SolveRequest request;
      request.inplane_modes = 0;
      request.points = 51;
      ForcedRequest forced;
      forced.end = end;
      forced.direction = direction;
      forced.amplitude_m = d;
      forced.omegas_rad_s = {0.0, 3.3, 27.0};
      request.forced = forced;
      const SolverOutput out = run(problem, request);
      ASSERT_EQ(out.forced.size(), 3u) << out.summary.full_report();
      for (const ForcedResponse& r : out.forced) {
        ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
        const bool axial = direction == ForcingDirection::Tangential;
        const double k =
            axial ? r.omega_rad_s * std::sqrt(1.0 / EA) : r.omega_rad_s * std::sqrt((1.0 + e) / T);
        for (Index j = 0; j < r.s_m.size(); ++j) {
          const double s = end == CableEnd::B ? r.s_m[j] : L - r.s_m[j];
          const double shape = k == 0.0 ? s / L : std::sin(k * s) / std::sin(k * L);
          const double slope = k == 0.0 ? 1.0 / L : k * std::cos(k * s) / std::sin(k * L);
          const double sign_a = end == CableEnd::B ? 1.0 : -1.0;  // d/ds of the mirror image
          const Vector& moving = axial ? r.u : (direction == ForcingDirection::Normal ? r.w : r.v);
          EXPECT_NEAR(moving[j], d * shape, 1e-10) << to_string(direction) << " " << to_string(end);
          const double tau = axial ? EA * d * slope * sign_a : 0.0;
          EXPECT_NEAR(r.tension_n[j], tau, 1e-8 * EA * d) << to_string(direction);
        }
      }
    }
  }
}

TEST(ShootingForced, StaticLimitMatchesFiniteDifferenceOfStatics) {
  // Central difference with step 1e-5 m: truncation ~1e-10 relative, rounding ~1e-16/1e-5.
  constexpr double kRelTol = 1e-6;
  const Problem mooring = catena::testing::mooring_line(Vec2(900.0, 300.0));
  Problem gale = make_gale_xi_problem(-1.383, 1.383);
  gale.prescribed_forces.reset();  // re-solved from the moved support below
  for (const Problem& problem : {gale, mooring}) {
    const StaticSolution statics = solve_statics(problem);
    const double L = problem.cable.length_m;
    for (ForcingDirection direction : {ForcingDirection::Tangential, ForcingDirection::Normal}) {
      const Vec2 unit =
          direction == ForcingDirection::Tangential ? statics.tangent(L) : statics.normal(L);
      const double step = 1e-5;
      Problem plus = problem, minus = problem;
      plus.supports.b_m += step * unit;
      minus.supports.b_m -= step * unit;
      const StaticSolution sp = solve_statics(plus), sm = solve_statics(minus);
      SolveRequest request;
      request.inplane_modes = 0;
      request.points = 11;
      ForcedRequest forced;
      forced.direction = direction;
      forced.amplitude_m = 1.0;  // linear: the response per metre
      forced.omegas_rad_s = {0.0};
      request.forced = forced;
      const SolverOutput out = run(problem, request, 1e-12);
      const ForcedResponse& r = out.forced.at(0);
      ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
      double scale = 0.0;
      for (Index j = 0; j < r.s_m.size(); ++j) {
        scale = std::max(scale, std::abs(r.tension_n[j]));
      }
      for (Index j = 0; j < r.s_m.size(); ++j) {
        const double s = r.s_m[j];
        const double dT = (sp.tension_n(s) - sm.tension_n(s)) / (2.0 * step);
        EXPECT_NEAR(r.tension_n[j], dT, kRelTol * scale)
            << "L " << L << " " << to_string(direction) << " s " << s;
        const Vec2 dr = (sp.offset_m(s) - sm.offset_m(s)) / (2.0 * step);
        EXPECT_NEAR(r.u[j], dr.dot(statics.tangent(s)), kRelTol) << "u at s " << s;
        EXPECT_NEAR(r.w[j], dr.dot(statics.normal(s)), kRelTol) << "w at s " << s;
      }
    }
  }
}

TEST(ShootingForced, ForcingAtANaturalFrequencyIsDiagnosed) {
  SolveRequest request;
  request.inplane_modes = 1;
  request.outofplane_modes = 0;
  const Problem problem = make_gale_sag_problem(0.0, 0.8);
  const SolverOutput modes = run(problem, request, 1e-10);
  ForcedRequest forced;
  forced.direction = ForcingDirection::Normal;
  forced.omegas_rad_s = {modes.inplane->modes[0].omega_rad_s};
  request.forced = forced;
  request.inplane_modes = 0;
  const SolverOutput out = run(problem, request, 1e-10);
  ASSERT_EQ(out.forced.size(), 1u);
  EXPECT_NE(out.forced[0].diagnostic.find("resonance"), std::string::npos);
  EXPECT_EQ(out.forced[0].u.size(), 0);
}

// Roots of the Bessel cross product for a hanging string T = T_A + W0 s (the exact reference).
std::vector<double> vertical_string_frequencies(double T_A, double W0, double M, double L, int n) {
  auto cross = [&](double omega) {
    const double zA = 2.0 * omega * std::sqrt(M * T_A) / W0;
    const double zB = 2.0 * omega * std::sqrt(M * (T_A + W0 * L)) / W0;
    using boost::math::cyl_bessel_j;
    using boost::math::cyl_neumann;
    return cyl_bessel_j(0, zA) * cyl_neumann(0, zB) - cyl_bessel_j(0, zB) * cyl_neumann(0, zA);
  };
  std::vector<double> roots;
  double step = 0.01, omega = step;
  double previous = cross(omega);
  while (static_cast<int>(roots.size()) < n) {
    const double next = cross(omega + step);
    if (previous * next < 0.0) {
      std::uintmax_t iterations = 100;
      const auto r = boost::math::tools::toms748_solve(
          cross, omega, omega + step, previous, next, boost::math::tools::eps_tolerance<double>(52),
          iterations);
      roots.push_back(0.5 * (r.first + r.second));
    }
    omega += step;
    previous = next;
  }
  return roots;
}

TEST(ShootingSolver, VerticalCableMatchesBesselString) {
  // Inextensible vertical cable, bottom support pulled down with 50 N, W0 = 10 N/m, L = 20 m.
  Problem problem;
  problem.cable.length_m = 20.0;
  problem.cable.weight_n_per_m = 10.0;
  problem.cable.mass_kg_per_m = 2.0;
  problem.cable.added_mass_kg_per_m = 0.5;
  problem.supports.b_m = Vec2(0.0, 20.0);
  problem.prescribed_forces = EndForces{0.0, 50.0};
  SolveRequest request;
  request.inplane_modes = 5;
  request.outofplane_modes = 5;
  const SolverOutput out = run(problem, request);
  ASSERT_EQ(out.summary.termination, Termination::Converged) << out.summary.full_report();
  const std::vector<double> exact = vertical_string_frequencies(50.0, 10.0, 2.5, 20.0, 5);
  for (int i = 0; i < 5; ++i) {
    EXPECT_LT(relative_error(out.outofplane->modes[i].omega_rad_s, exact[i]), 1e-10) << i;
    EXPECT_LT(relative_error(out.inplane->modes[i].omega_rad_s, exact[i]), 1e-10) << i;
  }
}

}  // namespace
}  // namespace catena
