// fe solver: eigenpair quality, the Sylvester-inertia mode count, the discrete statics, shapes,
// dynamic tension, forced response and bad input.
//
// References: exact properties of the discrete problem (M-orthogonality, residual, inertia), the
// continuous statics (the chain's element forces equal the catenary's force at element midpoints
// by construction; its nodes converge to the catenary at O(h^2)), and closed forms for a straight
// pre-tensioned bar (transverse and axial standing waves, their tension, and the forced response
// u = d sin(k s) / sin(k L)).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/models/problem_builders.hpp"
#include "catena/solvers/fe_solver.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "solvers/internal/fe_eigen.hpp"
#include "solvers/solver_test_support.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::relative_error;

using Solved = catena::testing::SolvedProblem;
using catena::testing::modes_request;

Solved solve(const Problem& problem, const SolveRequest& request, const FeSolverOptions& options) {
  return catena::testing::solve_problem(solve_fe, problem, request, options);
}

// The bounds for the eigenpairs: mass-orthogonality 1e-10, residual
// ||K phi - w^2 M phi|| / ||K phi|| below 1e-10. That residual has a rounding floor of about
// eps ||K|| / ||K phi|| ~ eps (EA / T) (2N / (pi n))^2, so it can hold only where the chain is not
// stiff: out of plane (no EA) and in plane for a small EA/T (the straight bar, EA/T = 10). For a
// stiff chain the normwise backward error ||r|| / ((||K|| + w^2 ||M||) ||phi||) is the measure
// that reaches rounding.
constexpr double kMaxOrthogonalityError = 1e-10;
constexpr double kMaxResidual = 1e-10;
constexpr double kMaxBackwardError = 1e-14;

internal::FeEigenSolution lowest_modes(const Problem& problem, Plane plane, int elements) {
  const StaticSolution statics = solve_statics(problem);
  const internal::FeChain chain =
      internal::solve_chain_statics(problem, statics, elements, problem.cable.axial_stiffness_n);
  const internal::FeMatrices matrices =
      plane == Plane::InPlane ? internal::assemble_inplane(chain) : internal::assemble_outofplane(chain);
  return internal::solve_lowest_modes(matrices, 10, 1e-13, 1000);
}

Problem straight_bar();

TEST(FeModel, ModesAreMassOrthogonalWithSmallResidualAndBackwardError) {
  const Problem inclined = make_taut_inclined_problem(0.1, 30.0, 50.0, 0.6);  // EA/T = 6667
  for (Plane plane : {Plane::InPlane, Plane::OutOfPlane}) {
    const internal::FeEigenSolution eigen = lowest_modes(inclined, plane, 800);
    ASSERT_EQ(eigen.termination, Termination::Converged) << eigen.message;
    EXPECT_LE(eigen.max_orthogonality_error, kMaxOrthogonalityError);
    EXPECT_LE(eigen.max_backward_error, kMaxBackwardError);
    EXPECT_EQ(eigen.inertia_count, 10);
    if (plane == Plane::OutOfPlane) {
      EXPECT_LE(eigen.max_residual, kMaxResidual);
    }
  }
  const internal::FeEigenSolution bar = lowest_modes(straight_bar(), Plane::InPlane, 400);
  ASSERT_EQ(bar.termination, Termination::Converged) << bar.message;
  EXPECT_LE(bar.max_residual, kMaxResidual);
  EXPECT_LE(bar.max_orthogonality_error, kMaxOrthogonalityError);
}

struct CountCase {
  std::string name;
  Problem problem;
};

std::vector<CountCase> count_cases() {
  const double crossover = 4.0 * kPi * kPi;
  return {
      {"taut_string", make_taut_inclined_problem(1e-6, 0.0, 1e-6, 1.0)},
      {"crossover_minus_phi0", make_taut_inclined_problem(0.01, 0.0, crossover - 1e-3, 1.0)},
      {"crossover_plus_phi0", make_taut_inclined_problem(0.01, 0.0, crossover + 1e-3, 1.0)},
      {"crossover_minus_phi20", make_taut_inclined_problem(0.01, 20.0, crossover - 1e-3, 1.0)},
      {"crossover_plus_phi20", make_taut_inclined_problem(0.01, 20.0, crossover + 1e-3, 1.0)},
      {"inclined_added_mass", make_taut_inclined_problem(0.1, 30.0, 100.0, 0.5)},
      {"steep_sagging", make_taut_inclined_problem(0.5, 45.0, 20.0, 1.0)},
      {"gale_symmetric", make_gale_xi_problem(-0.5, 0.5)},
      {"gale_inclined", make_gale_sag_problem(1.0, 0.8)},
      {"gale_deep_sag", make_gale_sag_problem(0.25, 0.6)},
  };
}

class ModeCountTest : public ::testing::TestWithParam<CountCase> {};

TEST_P(ModeCountTest, InertiaCountEqualsTheNumberOfReturnedModes) {
  constexpr int kModes = 8;
  const Solved solved = solve(GetParam().problem, modes_request(kModes, kModes), {.elements = 200});
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged) << solved.output.summary.full_report();
  for (const auto* result : {&*solved.output.inplane, &*solved.output.outofplane}) {
    ASSERT_EQ(result->modes.size(), static_cast<std::size_t>(kModes));
    EXPECT_EQ(result->proved_count_below_top, kModes) << result->summary.full_report();
    for (std::size_t i = 1; i < result->modes.size(); ++i)
      EXPECT_GT(result->modes[i].omega_rad_s, result->modes[i - 1].omega_rad_s);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ModeCountTest, ::testing::ValuesIn(count_cases()),
                         [](const auto& test_info) { return test_info.param.name; });

TEST(FeModel, NearCrossoverBothModesOfTheVeeringPairAreFound) {
  // At lambda^2 = 4 pi^2 the first symmetric and first antisymmetric modes meet (kL = 2 pi); just
  // beside it both must be returned, as modes 1 and 2, close to each other.
  const Solved solved = solve(make_taut_inclined_problem(0.01, 0.0, 4.0 * kPi * kPi + 1e-3, 1.0),
                              modes_request(4, 0), {.elements = 400});
  const auto& modes = solved.output.inplane->modes;
  ASSERT_EQ(modes.size(), 4u);
  EXPECT_NEAR(modes[0].k_l_over_pi, 2.0, 1e-3);
  EXPECT_NEAR(modes[1].k_l_over_pi, 2.0, 1e-3);
  EXPECT_GT(modes[2].k_l_over_pi, 2.5);
  EXPECT_EQ(solved.output.inplane->proved_count_below_top, 4);
}

// The element forces are the continuous force at the element midpoints (exact by construction),
// and the nodes converge to the catenary at O(h^2): with h = L/400 within 1e-5 of the chord.
constexpr double kRelTolChainPosition = 1e-5;

TEST(FeModel, DiscreteStaticsClosesOnSupportBAndApproachesTheCatenary) {
  Problem problem;
  problem.cable = {.length_m = 1000.0, .weight_n_per_m = 1000.0, .axial_stiffness_n = 5e8,
                   .mass_kg_per_m = 120.0, .added_mass_kg_per_m = 80.0};
  problem.supports.b_m = Vec2(900.0, 300.0);
  const StaticSolution statics = solve_statics(problem);
  const internal::FeChain chain =
      internal::solve_chain_statics(problem, statics, 400, problem.cable.axial_stiffness_n);
  EXPECT_LE(chain.closure_error_m, 1e-9);
  EXPECT_GT(chain.newton_iterations, 0);
  const double chord = problem.supports.chord_m().norm();
  for (int i = 0; i <= 400; i += 50) {
    const double s = i * chain.element_length_m;
    const Vec2 difference = chain.node_offset_m[static_cast<std::size_t>(i)] - statics.offset_m(s);
    EXPECT_LE(difference.norm() / chord, kRelTolChainPosition) << "node " << i;
  }
  EXPECT_LE(relative_error(chain.horizontal_force_n, statics.horizontal_force_n()), 1e-4);
}

// A straight bar: L = 1 m, EA = 10 N, m = 1 kg/m, stretched to 1.1 m (T = 1 N), weight 1e-9 N/m.
Problem straight_bar() {
  Problem problem;
  problem.cable.length_m = 1.0;
  problem.cable.weight_n_per_m = 1e-9;
  problem.cable.axial_stiffness_n = 10.0;
  problem.cable.mass_kg_per_m = 1.0;
  problem.supports.b_m = Vec2(1.1, 0.0);
  return problem;
}

// Linear interpolation of sin between nodes: (pi h)^2 / 8 ~ 2e-6 at h = 1/800; tension at the end
// stations extrapolated from the two nearest element midpoints: ~ 0.4 (pi h)^2 ~ 6e-6.
constexpr double kTolShape = 1e-4;

TEST(FeModel, StraightBarShapesTensionAndModalMassAreTheStandingWaves) {
  SolveRequest request = modes_request(6, 2);
  request.shapes = true;
  request.tension = true;
  request.points = 51;
  const Solved solved = solve(straight_bar(), request, {.elements = 400});
  ASSERT_EQ(solved.output.summary.termination, Termination::Converged) << solved.output.summary.full_report();
  const CableProperties& cable = solved.problem.cable;
  int transverse = 0, axial = 0;
  for (const Mode& mode : solved.output.inplane->modes) {
    const bool is_axial = mode.normalised_by == "u";
    const int n = is_axial ? ++axial : ++transverse;
    const Vector& along = is_axial ? mode.u : mode.w;
    const Vector& across = is_axial ? mode.w : mode.u;
    // The exact shape sin(n pi s / L), scaled like ours: to 1 at the station of largest amplitude
    // (the peak may fall between stations).
    Vector exact(mode.s_m.size());
    for (Index j = 0; j < mode.s_m.size(); ++j) exact[j] = std::sin(n * kPi * mode.s_m[j] / cable.length_m);
    const double peak = exact.cwiseAbs().maxCoeff();
    double max_error = 0.0;
    for (Index j = 0; j < mode.s_m.size(); ++j)
      max_error = std::max(max_error, std::abs(std::abs(along[j]) - std::abs(exact[j]) / peak));
    EXPECT_LE(max_error, kTolShape) << (is_axial ? "axial " : "transverse ") << n;
    EXPECT_LE(across.cwiseAbs().maxCoeff(), kTolShape);
    // Modal mass of the scaled sin(n pi s / L) by the trapezoid rule on the stations: m L / 2 / peak^2
    // (M = m here), to O(1/points^2) = 4e-4.
    EXPECT_NEAR(mode.modal_mass_kg, 0.5 * cable.mass_kg_per_m * cable.length_m / (peak * peak), 1e-3);
    if (is_axial) {
      const double tension = cable.axial_stiffness_n * n * kPi / cable.length_m / peak;
      EXPECT_LE(relative_error(mode.max_abs_tension_n, tension), kTolShape) << "axial " << n;
    } else {
      EXPECT_LE(mode.max_abs_tension_n, kTolShape) << "transverse " << n;
    }
  }
  EXPECT_EQ(axial, 1);
  for (const Mode& mode : solved.output.outofplane->modes) {
    EXPECT_EQ(mode.normalised_by, "v");
    EXPECT_NEAR(mode.v.cwiseAbs().maxCoeff(), 1.0, 1e-12);
  }
}

TEST(FeModel, ForcedResponseOfAStraightBarMatchesTheStandingWave) {
  const Problem problem = straight_bar();
  const StaticSolution statics = solve_statics(problem);
  const double T = statics.tension_n(0.5);
  const double strain = T / problem.cable.axial_stiffness_n;
  const double omega = 5.0, amplitude = 0.01;
  for (ForcingDirection direction :
       {ForcingDirection::Tangential, ForcingDirection::Normal, ForcingDirection::OutOfPlane}) {
    SolveRequest request = modes_request(0, 0);
    request.points = 21;
    request.forced = ForcedRequest{.end = CableEnd::B, .direction = direction, .amplitude_m = amplitude,
                                   .omegas_rad_s = {omega}};
    const Solved solved = solve(problem, request, {.elements = 400});
    ASSERT_EQ(solved.output.forced.size(), 1u);
    const ForcedResponse& response = solved.output.forced[0];
    ASSERT_TRUE(response.diagnostic.empty()) << response.diagnostic;
    const bool axial = direction == ForcingDirection::Tangential;
    const double k = axial ? omega * std::sqrt(problem.cable.mass_kg_per_m / problem.cable.axial_stiffness_n)
                           : omega * std::sqrt(problem.cable.normal_mass_kg_per_m() * (1.0 + strain) / T);
    const Vector& moving = axial ? response.u : (direction == ForcingDirection::Normal ? response.w : response.v);
    for (Index j = 0; j < response.s_m.size(); ++j) {
      const double s = response.s_m[j];
      const double exact = amplitude * std::sin(k * s) / std::sin(k * problem.cable.length_m);
      EXPECT_NEAR(moving[j], exact, kTolShape * amplitude) << "s = " << s;
      if (axial) {
        const double tension = problem.cable.axial_stiffness_n * amplitude * k * std::cos(k * s) /
                               std::sin(k * problem.cable.length_m);
        EXPECT_NEAR(response.tension_n[j], tension, kTolShape * std::abs(tension) + 1e-9) << "s = " << s;
      }
    }
  }
}

// The quasi-static (omega = 0) response of an inextensible catenary to a tangential end
// displacement is the derivative of the exact nonlinear statics: max_s |dT(s)| for support b moved
// along its tangent (finite differences of the shared solve_statics, step 1e-6 a: error ~1e-6).
// The fe value goes through the kappa penalty and its extrapolation.
constexpr double kRelTolQuasiStaticTension = 1e-4;

TEST(FeModel, QuasiStaticTensionOfAnInextensibleCatenaryIsTheStaticsDerivative) {
  const Problem problem = make_gale_sag_problem(0.5, 0.8);
  Problem base = problem;
  base.prescribed_forces.reset();
  const StaticSolution before = solve_statics(base);
  const double L = problem.cable.length_m, delta = 1e-6;
  Problem moved = base;
  moved.supports.b_m += delta * before.tangent(L);
  const StaticSolution after = solve_statics(moved);
  double expected = 0.0;
  for (int i = 0; i <= 200; ++i) {
    const double s = L * i / 200.0;
    expected = std::max(expected, std::abs(after.tension_n(s) - before.tension_n(s)) / delta);
  }
  SolveRequest request = modes_request(0, 0);
  request.points = 201;
  request.forced = ForcedRequest{.end = CableEnd::B, .direction = ForcingDirection::Tangential,
                                 .amplitude_m = 1.0, .omegas_rad_s = {0.0}};
  const Solved solved = solve(problem, request, {.elements = 400});
  ASSERT_TRUE(solved.output.forced[0].diagnostic.empty()) << solved.output.forced[0].diagnostic;
  EXPECT_LE(relative_error(solved.output.forced[0].max_abs_tension_n, expected), kRelTolQuasiStaticTension)
      << solved.output.forced[0].max_abs_tension_n << " vs " << expected;
}

TEST(FeModel, ForcingAtANaturalFrequencyGivesADiagnosticNotInfinity) {
  const Problem problem = make_taut_inclined_problem(0.1, 10.0, 30.0, 1.0);
  const Solved modal = solve(problem, modes_request(3, 0), {.elements = 200});
  SolveRequest request = modes_request(3, 0);
  request.forced = ForcedRequest{.end = CableEnd::B, .direction = ForcingDirection::Normal,
                                 .amplitude_m = 0.01,
                                 .omegas_rad_s = {modal.output.inplane->modes[1].omega_rad_s, 0.5}};
  const Solved solved = solve(problem, request, {.elements = 200});
  ASSERT_EQ(solved.output.forced.size(), 2u);
  EXPECT_NE(solved.output.forced[0].diagnostic.find("resonance"), std::string::npos);
  EXPECT_TRUE(solved.output.forced[0].u.allFinite());
  EXPECT_TRUE(solved.output.forced[1].diagnostic.empty());
  EXPECT_TRUE(solved.output.forced[1].w.allFinite());
  EXPECT_TRUE(std::isfinite(solved.output.forced[1].max_abs_tension_n));
}

void expect_invalid(const std::function<void()>& call, const std::string& fragment) {
  try {
    call();
    ADD_FAILURE() << "no InvalidInput thrown (expected one naming '" << fragment << "')";
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

TEST(FeSolverOptions, RejectsBadValuesAndTooManyModes) {
  const Problem problem = make_taut_inclined_problem(0.1, 0.0, 10.0, 1.0);
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  auto run = [&](const FeSolverOptions& options, int inplane, int outofplane) {
    return [&, options, inplane, outofplane] {
      solve_fe(problem, statics, groups, modes_request(inplane, outofplane), options);
    };
  };
  expect_invalid(run({.elements = 1}, 1, 0), "elements");
  expect_invalid(run({.elements = 1000, .kappa = 0.0}, 1, 0), "kappa");
  expect_invalid(run({.elements = 1000, .kappa = -1e-6}, 1, 0), "kappa");
  expect_invalid(run({.elements = 3}, 5, 0), "too few for 5 in-plane modes");
  expect_invalid(run({.elements = 5}, 0, 5), "too few for 5 out-of-plane modes");
  // The largest mode count that fits is accepted (dense path for tiny problems).
  const SolverOutput tiny = solve_fe(problem, statics, groups, modes_request(4, 2), {.elements = 3});
  EXPECT_EQ(tiny.inplane->modes.size(), 4u);
  EXPECT_EQ(tiny.outofplane->modes.size(), 2u);
  // Too coarse for the N/2 error-estimate mesh and for an observed order: still a clean answer.
  const SolverOutput coarse = solve_fe(problem, statics, groups, modes_request(3, 0),
                                       {.elements = 3, .richardson = false, .observed_order = true});
  ASSERT_EQ(coarse.inplane->modes.size(), 3u);
  EXPECT_TRUE(std::isfinite(coarse.inplane->modes[0].omega_rad_s));
}

TEST(FeSolverOptions, RegistryKnobsAreValidated) {
  const SolverEntry* entry = find_solver("fe");
  ASSERT_NE(entry, nullptr);
  EXPECT_NO_THROW(entry->validate_knobs({{"elements", 100L}, {"richardson", false}, {"kappa", 1e-5}}));
  expect_invalid([&] { entry->validate_knobs({{"elements", 1L}}); }, "[solvers.fe].elements");
  expect_invalid([&] { entry->validate_knobs({{"kappa", 0.0}}); }, "[solvers.fe].kappa");
  expect_invalid([&] { entry->validate_knobs({{"elemnts", 10L}}); }, "elemnts");
  // End to end through the registry, as `catena solve` runs it.
  const Problem problem = make_gale_xi_problem(-0.5, 0.5);
  const StaticSolution statics = solve_statics(problem);
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  const SolveRequest request = modes_request(3, 3);
  const SolveContext context{problem, statics, groups, request};
  const SolverOutput output = run_solver(*entry, context, {{"elements", 200L}, {"kappa", 1e-6}});
  EXPECT_EQ(output.summary.termination, Termination::Converged) << output.summary.full_report();
  EXPECT_EQ(output.solver, "fe");
  EXPECT_GT(output.summary.wall_time_s, 0.0);
  ASSERT_TRUE(output.inplane && output.outofplane);
  EXPECT_NEAR(*output.inplane->modes[0].gale_ratio, 2.59, 0.005);
}

}  // namespace
}  // namespace catena
