// SPDX-License-Identifier: MIT
// fe on the seabed (docs/explanation/methods/fe.md, "Seabed contact"), against anchors that need no
// other solver:
// - a line lying entirely on the seabed, taut (tension H, C_B = 0): the exact frequencies of a
//   tensioned string on a Winkler foundation, omega^2 = (H/(1+e) (n pi/L)^2 + k) / M with
//   e = H/EA, L unstretched and k per unstretched length (k_t out of plane, k_s for the vertical
//   motion in plane), and of a bar on a foundation, omega^2 = (EA (n pi/L)^2 + k_t) / m (axial);
// - the discrete statics of the 40 %-grounded line converges to the continuous one at O(l0^2);
// - the 40 %-grounded line: observed order 2 of the unextrapolated frequencies in the mesh size,
//   the mode count proved by inertia, convergence in k_s;
// - touchdown exactly at A reproduces the line without a seabed;
// - a slack grounded stretch (friction) without foundation stiffness across it is declined;
// - a U (both ends above the seabed, a grounded middle; tests/solvers/common/contact_states.hpp):
//   the discrete statics converges to the continuous one at O(l0^2) with the middle stretch's
//   nodes on the seabed, and both of its contact boundaries get a layer piece.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "catena/core/types.hpp"
#include "catena/solvers/fe_solver.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/seabed_statics.hpp"
#include "solvers/common/contact_states.hpp"
#include "solvers/common/solver_test_support.hpp"
#include "solvers/fe/fe_chain_statics.hpp"
#include "solvers/fe/fe_levels.hpp"
#include "solvers/fe/fe_line_mesh.hpp"
#include "solvers/fe/fe_operators.hpp"
#include "solvers/fe/fe_structured_residual.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

using catena::testing::modes_request;
using catena::testing::relative_error;

// A 100 m line with EA/H = 1e3 lying on the seabed at z = -50, pulled to tension H.
constexpr double kLength = 100.0, kTension = 2e4, kAxial = 2e7, kMass = 40.0, kAdded = 10.0;
constexpr double kVertical = 3e4, kTangential = 1.5e3;

Problem line_on_seabed() {
  Problem p;
  p.cable = {kLength, 300.0, kAxial, kMass, kAdded};
  p.supports.a_m = Vec2(0.0, -50.0);
  p.supports.b_m = Vec2(kLength * (1.0 + kTension / kAxial), -50.0);
  p.seabed = Seabed{-50.0, 0.0, kVertical, kTangential};
  return p;
}

SolverOutput solve_grounded(const Problem& problem,
                            const StaticSolution& statics,
                            const SolveRequest& request,
                            const FeSolverOptions& options) {
  const DimensionlessGroups groups = compute_dimensionless_groups(problem, statics);
  return solve_fe(problem, statics, groups, request, options);
}

std::vector<double> sorted_first(std::vector<double> values, int count) {
  std::sort(values.begin(), values.end());
  values.resize(static_cast<std::size_t>(count));
  return values;
}

TEST(FeSeabed, TheStructuredForcedResidualCarriesTheFoundation) {
  // fe_structured_residual.hpp on a grounded chain: the foundation's springs are part of
  // f - (K - w^2 M) x, as in the assembled stiffness.
  const Problem problem = line_on_seabed();
  const StaticSolution statics(problem.as_line(), problem.supports.a_m, *problem.seabed, kTension,
                               kLength);
  FeSolverOptions options;
  options.elements = 20;
  options.richardson = false;
  const internal::FePlan plan = internal::make_fe_plan(problem, statics, options, 1, 0);
  internal::FeTimings timings;
  std::string failure;
  const internal::FeLevels levels =
      internal::solve_level_statics(problem, statics, plan, timings, failure);
  ASSERT_TRUE(failure.empty()) << failure;
  const internal::FeChain& chain = levels[static_cast<std::size_t>(plan.main_fine)][0].chain;
  ASSERT_TRUE(chain.has_contact());
  const internal::FeMatrices matrices = internal::assemble(Plane::InPlane, chain);
  Vector x(matrices.stiffness.rows());
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = 1e-3 * std::cos(0.9 * static_cast<double>(i));
  const Vec2 end_b(1e-3, 0.0);
  Vector ends(4);
  ends << Vec2::Zero(), end_b;
  const double omega = 2.0;
  const Vector assembled = -(matrices.boundary_coupling * ends) -
                           (matrices.stiffness * x - omega * omega * (matrices.mass * x));
  const Vector structured =
      internal::inplane_structured_residual(chain, matrices, omega, x, Vec2::Zero(), end_b);
  const double l0 = kLength / chain.elements;
  const double rounding = 1e3 * std::numeric_limits<double>::epsilon() * kAxial / l0 * 2e-3;
  EXPECT_LE((structured - assembled).cwiseAbs().maxCoeff(), rounding);
  EXPECT_GT(kTangential * l0 * 1e-3, 1e3 * rounding);  // the foundation's force is resolved
}

TEST(FeSeabed, LineOnTheSeabedIsAStringAndABarOnAWinklerFoundation) {
  const Problem problem = line_on_seabed();
  const StaticSolution statics(problem.as_line(), problem.supports.a_m, *problem.seabed, kTension,
                               kLength);
  ASSERT_TRUE(statics.has_contact());
  FeSolverOptions options;
  options.elements = 1000;
  const SolverOutput out = solve_grounded(problem, statics, modes_request(8, 6), options);
  ASSERT_TRUE(out.outofplane && out.inplane) << out.summary.message;
  ASSERT_EQ(out.outofplane->modes.size(), 6u) << out.outofplane->summary.message;
  ASSERT_EQ(out.inplane->modes.size(), 8u) << out.inplane->summary.message;
  const double e = kTension / kAxial, M = kMass + kAdded, m = kMass;
  auto string = [&](int n, double k) {
    return std::sqrt((kTension / (1 + e) * std::pow(n * kPi / kLength, 2) + k) / M);
  };
  auto bar = [&](int n) {
    return std::sqrt((kAxial * std::pow(n * kPi / kLength, 2) + kTangential) / m);
  };
  for (int n = 1; n <= 6; ++n) {
    const Mode& mode = out.outofplane->modes[static_cast<std::size_t>(n) - 1];
    EXPECT_LT(relative_error(mode.omega_rad_s, string(n, kTangential)), 1e-9)
        << "out of plane n = " << n;
    EXPECT_LT(relative_error(mode.omega_rad_s, string(n, kTangential)),
              mode.relative_error_estimate);
  }
  std::vector<double> inplane;
  for (int n = 1; n <= 8; ++n) inplane.push_back(string(n, kVertical));
  for (int n = 1; n <= 8; ++n) inplane.push_back(bar(n));
  inplane = sorted_first(inplane, 8);
  for (int i = 0; i < 8; ++i) {
    const Mode& mode = out.inplane->modes[static_cast<std::size_t>(i)];
    EXPECT_LT(relative_error(mode.omega_rad_s, inplane[static_cast<std::size_t>(i)]), 1e-9)
        << "in plane " << i + 1;
  }
  EXPECT_EQ(out.inplane->proved_count_below_top, 8);
  EXPECT_EQ(out.outofplane->proved_count_below_top, 6);
}

}  // namespace
}  // namespace catena
namespace catena {
namespace {
// k_s = k_t = 0 with contact: the grounded line is a free string on the seabed (bilateral
// contact), omega_n = (n pi / L) sqrt(H / ((1 + e) M)) in both transverse directions.
TEST(FeSeabed, WithoutFoundationTheGroundedLineIsAFreeString) {
  Problem problem = line_on_seabed();
  problem.seabed->stiffness_n_per_m2 = 0.0;
  problem.seabed->tangential_stiffness_n_per_m2 = 0.0;
  const StaticSolution statics(problem.as_line(), problem.supports.a_m, *problem.seabed, kTension,
                               kLength);
  FeSolverOptions options;
  options.elements = 400;
  const SolverOutput out = solve_grounded(problem, statics, modes_request(4, 4), options);
  ASSERT_TRUE(out.inplane && out.outofplane) << out.summary.message;
  ASSERT_EQ(out.inplane->modes.size(), 4u) << out.inplane->summary.message;
  const double c = std::sqrt(kTension / ((1.0 + kTension / kAxial) * (kMass + kAdded)));
  for (std::size_t i = 0; i < 4; ++i) {
    const double exact = (static_cast<double>(i) + 1.0) * kPi / kLength * c;
    EXPECT_LT(relative_error(out.inplane->modes[i].omega_rad_s, exact), 1e-9)
        << "in plane " << i + 1;
    EXPECT_LT(relative_error(out.outofplane->modes[i].omega_rad_s, exact), 1e-9)
        << "out of plane " << i + 1;
  }
}

// The forced response of the line lying on the seabed, end B driven at omega, against the exact
// solutions of the bar and string on a foundation with A fixed: X(s) = d sin(q s) / sin(q L) with
// q^2 = (omega^2 m - k_t) / EA (axial, tension EA X'), q^2 = (omega^2 M - k) (1 + e) / H (vertical
// with k_s, out of plane with k_t; sinh where q^2 < 0).
double exact_forced(double q2, double s) {
  if (q2 > 0.0) return std::sin(std::sqrt(q2) * s) / std::sin(std::sqrt(q2) * kLength);
  return std::sinh(std::sqrt(-q2) * s) / std::sinh(std::sqrt(-q2) * kLength);
}

TEST(FeSeabed, ForcedResponseOfTheLineOnTheSeabedIsExact) {
  const Problem problem = line_on_seabed();
  const StaticSolution statics(problem.as_line(), problem.supports.a_m, *problem.seabed, kTension,
                               kLength);
  const double e = kTension / kAxial, d = 0.01;
  struct Case {
    ForcingDirection direction;
    double omega, q2;
  };
  const double M = kMass + kAdded;
  const std::vector<Case> cases = {
      {ForcingDirection::Tangential, 20.0, (400.0 * kMass - kTangential) / kAxial},
      {ForcingDirection::Normal, 20.0, (400.0 * M - kVertical) * (1 + e) / kTension},
      {ForcingDirection::OutOfPlane, 6.0, (36.0 * M - kTangential) * (1 + e) / kTension}};
  for (const Case& c : cases) {
    SolveRequest request = modes_request(0, 0);
    request.points = 41;
    request.forced = ForcedRequest{};
    request.forced->direction = c.direction;
    request.forced->amplitude_m = d;
    request.forced->omegas_rad_s = {c.omega};
    FeSolverOptions options;
    options.elements = 2000;
    const SolverOutput out = solve_grounded(problem, statics, request, options);
    ASSERT_EQ(out.forced.size(), 1u) << out.summary.message;
    const ForcedResponse& r = out.forced.front();
    ASSERT_TRUE(r.diagnostic.empty()) << r.diagnostic;
    const Vector& X = c.direction == ForcingDirection::Tangential ? r.u
                      : c.direction == ForcingDirection::Normal   ? r.w
                                                                  : r.v;
    double worst = 0.0, worst_tension = 0.0;
    for (Index k = 0; k < r.s_m.size(); ++k) {
      worst = std::max(worst, std::abs(X[k] - d * exact_forced(c.q2, r.s_m[k])) / d);
      if (c.direction == ForcingDirection::Tangential) {
        const double q = std::sqrt(c.q2);
        const double tension = kAxial * d * q * std::cos(q * r.s_m[k]) / std::sin(q * kLength);
        worst_tension =
            std::max(worst_tension, std::abs(r.tension_n[k] - tension) / r.max_abs_tension_n);
      }
    }
    // Measured at N = 2000: 5e-10 axial, 3e-11 vertical, 1e-9 out of plane (6e-7 and 4e-8 at
    // N = 500 and 1000: the order 4 of Richardson).
    EXPECT_LT(worst, 1e-8) << "direction " << static_cast<int>(c.direction);
    if (c.direction == ForcingDirection::Tangential) {
      EXPECT_LT(worst_tension, 1e-8);
      EXPECT_LT(worst_tension, r.relative_error_estimate);
    }
  }
}

SolverOutput solve_forty(double friction,
                         double vertical_stiffness,
                         int elements,
                         bool richardson = true) {
  const Problem problem = testing::forty_percent_grounded_chain(friction, vertical_stiffness);
  const StaticSolution statics = solve_seabed_statics(problem);
  FeSolverOptions options;
  options.elements = elements;
  options.richardson = richardson;
  options.tolerance = 0.0;  // these meshes (the tests compare meshes and orders)
  return solve_grounded(problem, statics, modes_request(10, 10), options);
}

// The discrete chain's horizontal force and touchdown vertical force converge to the continuous
// statics' (H, 0) at O(l0^2): the error falls by 4 per halving.
TEST(FeSeabed, DiscreteStaticsConvergesAtSecondOrder) {
  for (double friction : {0.0, 0.1}) {
    const Problem problem = testing::forty_percent_grounded_chain(friction, 3e6);
    const StaticSolution statics = solve_seabed_statics(problem);
    std::vector<double> h_error, v_error;
    for (int N : {100, 200, 400}) {
      const internal::FeLineMesh mesh = internal::make_line_mesh(problem, statics, N);
      const internal::FeChain chain =
          internal::solve_chain_statics(problem, statics, mesh, problem.cable.axial_stiffness_n);
      ASSERT_TRUE(chain.in_equilibrium()) << chain.failure;
      ASSERT_GT(chain.grounded_elements, 0);
      h_error.push_back(std::abs(chain.horizontal_force_n - statics.horizontal_force_n()));
      v_error.push_back(std::abs(chain.vertical_force_a_n));
    }
    for (std::size_t k = 0; k + 1 < h_error.size(); ++k) {
      EXPECT_NEAR(std::log2(h_error[k] / h_error[k + 1]), 2.0, 0.1) << "C_B = " << friction;
      EXPECT_NEAR(std::log2(v_error[k] / v_error[k + 1]), 2.0, 0.1) << "C_B = " << friction;
    }
    EXPECT_LT(h_error.back() / statics.horizontal_force_n(), 1e-5);
  }
}

// Without Richardson the frequencies of the 40 %-grounded line converge at O(l0^2), with and
// without friction, in both planes.
TEST(FeSeabed, ObservedOrderTwoOnTheGroundedLine) {
  for (double friction : {0.0, 0.1}) {
    std::vector<SolverOutput> out;
    for (int N : {200, 400, 800}) out.push_back(solve_forty(friction, 3e6, N, false));
    for (int i : {0, 4, 9}) {
      for (bool inplane : {true, false}) {
        auto omega = [&](std::size_t k) {
          return (inplane ? out[k].inplane : out[k].outofplane)
              ->modes[static_cast<std::size_t>(i)]
              .omega_rad_s;
        };
        const double order = std::log2((omega(0) - omega(1)) / (omega(1) - omega(2)));
        EXPECT_NEAR(order, 2.0, 0.05)
            << "C_B = " << friction << (inplane ? " in" : " out") << " mode " << i + 1;
      }
    }
  }
}

// The 40 %-grounded line with 10 modes per plane: converged, the mode count proved by inertia,
// the N = 1600 and 3200 results within their estimates of each other.
TEST(FeSeabed, FortyPercentGroundedConvergesWithinItsEstimate) {
  for (double friction : {0.0, 0.1}) {
    const SolverOutput coarse = solve_forty(friction, 3e6, 1600),
                       fine = solve_forty(friction, 3e6, 3200);
    for (bool inplane : {true, false}) {
      const ModalResult& a = *(inplane ? coarse.inplane : coarse.outofplane);
      const ModalResult& b = *(inplane ? fine.inplane : fine.outofplane);
      ASSERT_EQ(a.summary.termination, Termination::Converged) << a.summary.message;
      ASSERT_EQ(b.modes.size(), 10u);
      EXPECT_EQ(b.proved_count_below_top, 10);
      for (std::size_t i = 0; i < 10; ++i)
        EXPECT_LT(relative_error(a.modes[i].omega_rad_s, b.modes[i].omega_rad_s),
                  a.modes[i].relative_error_estimate);
    }
    // The summary says which dynamic model of the contact fe solved.
    const std::vector<std::string>& notes = coarse.summary.notes;
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& note) {
      return note.find("Winkler foundation (k_s = 3e+06") != std::string::npos;
    }));
  }
}

// As k_s grows the grounded part's vertical motion is confined to a layer of width
// sqrt(H / k_s) at the touchdown point, so the frequencies approach the rigid-seabed limit as
// k_s^(-1/2): each tenfold k_s shrinks the change by sqrt(10) (observed order 1/2 in k_s).
TEST(FeSeabed, FrequenciesConvergeAsTheSeabedStiffens) {
  std::vector<double> omega;
  for (double ks : {3e5, 3e6, 3e7, 3e8, 3e9})
    omega.push_back(solve_forty(0.1, ks, 800).inplane->modes[0].omega_rad_s);
  for (std::size_t k = 0; k + 2 < omega.size(); ++k) {
    const double order = std::log10((omega[k + 1] - omega[k]) / (omega[k + 2] - omega[k + 1]));
    EXPECT_NEAR(order, 0.5, 0.01) << "k_s = 3e" << k + 5;
  }
}

// A touchdown exactly at A (the free line leaves A horizontally): the statics finds at most a
// rounding-sized grounded length, and fe's frequencies equal those of the line without a seabed.
TEST(FeSeabed, TouchdownAtTheAnchorReproducesTheFreeLine) {
  Problem free_line;
  free_line.cable = {1000.0, 1200.0, 8e8, 150.0, 20.0};
  free_line.supports.a_m = Vec2(0.0, -200.0);
  free_line.supports.b_m = free_line.supports.a_m + catenary_end_offset(free_line.cable, 5e5, 0.0);
  Problem on_seabed = free_line;
  on_seabed.seabed = Seabed{-200.0, 0.1, 3e6, 1e4};
  const StaticSolution free_statics = solve_statics(free_line),
                       seabed_statics = solve_seabed_statics(on_seabed);
  ASSERT_LT(seabed_statics.grounded_length_m(), 1e-6);
  FeSolverOptions options;
  options.elements = 400;
  const SolverOutput a = solve_grounded(free_line, free_statics, modes_request(6, 6), options);
  const SolverOutput b = solve_grounded(on_seabed, seabed_statics, modes_request(6, 6), options);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_LT(relative_error(a.inplane->modes[i].omega_rad_s, b.inplane->modes[i].omega_rad_s),
              1e-9)
        << b.inplane->summary.message;
    EXPECT_LT(
        relative_error(a.outofplane->modes[i].omega_rad_s, b.outofplane->modes[i].omega_rad_s),
        1e-9);
  }
}

// Friction C_B = 3 (its drop 3 w L_g exceeds H) leaves part of the grounded length without tension:
// out of plane (k_t = 0) it has no stiffness, and fe declines that plane saying what to change; in
// plane the vertical foundation holds it (and the axial EA), so that plane is solved. With k_s = 0
// both decline.
TEST(FeSeabed, SlackGroundedStretchWithoutFoundationIsDeclined) {
  const SolverOutput out = solve_forty(3.0, 3e6, 400);
  ASSERT_TRUE(out.outofplane && out.inplane);
  EXPECT_EQ(out.outofplane->summary.termination, Termination::NotApplicable);
  EXPECT_NE(out.outofplane->summary.message.find("[seabed].tangential_stiffness > 0"),
            std::string::npos)
      << out.outofplane->summary.message;
  EXPECT_TRUE(out.outofplane->modes.empty());
  EXPECT_EQ(out.inplane->summary.termination, Termination::Converged)
      << out.inplane->summary.message;
  const SolverOutput soft = solve_forty(3.0, 0.0, 400);
  EXPECT_EQ(soft.inplane->summary.termination, Termination::NotApplicable);
  EXPECT_NE(soft.inplane->summary.message.find("[seabed].stiffness > 0"), std::string::npos);
}

// A U of chain (arcs of 150 m with H = 200 kN, 100 m grounded between them, k_s = 1e5).
testing::ContactState u_shape_chain(double k_s = 1e5) {
  return testing::u_shape({0.0, 1000.0, 5e8, 120.0, 20.0}, 2e5, 150.0, 100.0,
                          Seabed{0.0, 0.0, k_s, 1e4});
}

// Both ends of the grounded middle are contact boundaries: each gets a layer of 10 sqrt(H / k)
// on the grounded side (k = max(k_s, k_t)) with 320 elements.
TEST(FeSeabed, TheGroundedMiddleOfAUHasALayerAtBothBoundaries) {
  const testing::ContactState u = u_shape_chain();
  const internal::FeLineMesh mesh = internal::make_line_mesh(u.problem, u.statics, 400);
  ASSERT_EQ(mesh.pieces.size(), 5u);
  const double layer = 10.0 * std::sqrt(2e5 / 1e5);
  for (std::size_t p : {1u, 3u}) {
    EXPECT_TRUE(mesh.pieces[p].grounded);
    EXPECT_NEAR(mesh.pieces[p].section.length_m, layer, 1e-12);
    EXPECT_EQ(mesh.pieces[p].elements, 320);
  }
  EXPECT_TRUE(mesh.pieces[2].grounded);
  EXPECT_NEAR(mesh.pieces[2].section.length_m, 100.0 - 2.0 * layer, 1e-12);
  EXPECT_FALSE(mesh.pieces[0].grounded || mesh.pieces[4].grounded);
}

// The U's discrete statics: H and the two stretches' vertical forces (V_A at A, 0 where the
// second arc leaves the seabed) converge to the continuous ones at O(l0^2); the grounded nodes
// lie on the seabed (the condition on the middle stretch's first node) and the tension there is
// the chain's H.
TEST(FeSeabed, DiscreteStaticsOfAUConvergesAtSecondOrder) {
  const testing::ContactState u = u_shape_chain();
  const double V_A = u.statics.vertical_force_a_n();
  std::vector<double> h_error, a_error, v_error;
  for (int N : {100, 200, 400}) {
    const internal::FeLineMesh mesh = internal::make_line_mesh(u.problem, u.statics, N);
    const internal::FeChain chain = internal::solve_chain_statics(u.problem, u.statics, mesh, 5e8);
    ASSERT_TRUE(chain.in_equilibrium()) << chain.failure;
    ASSERT_EQ(chain.stretch_vertical_force_n.size(), 2);
    for (int i = 0; i <= chain.elements; ++i) {
      const bool on_seabed =
          (i < chain.elements && chain.is_grounded(i)) || (i > 0 && chain.is_grounded(i - 1));
      if (on_seabed) {
        EXPECT_NEAR(chain.node_offset_m[static_cast<std::size_t>(i)].y(), chain.seabed_offset_z_m,
                    1e-9)
            << "node " << i;
      }
    }
    for (int j = 0; j < chain.elements; ++j) {
      if (chain.is_grounded(j)) {
        EXPECT_EQ(chain.tension_n[j], chain.horizontal_force_n);
      }
    }
    h_error.push_back(std::abs(chain.horizontal_force_n - u.statics.horizontal_force_n()));
    a_error.push_back(std::abs(chain.stretch_vertical_force_n[0] - V_A));
    v_error.push_back(std::abs(chain.stretch_vertical_force_n[1]));
    std::printf("N = %d: H - H_continuous %.3e N, V_A error %.3e N, lift-off V %.3e N\n",
                chain.elements, h_error.back(), a_error.back(), v_error.back());
  }
  for (std::size_t k = 0; k + 1 < h_error.size(); ++k) {
    EXPECT_NEAR(std::log2(h_error[k] / h_error[k + 1]), 2.0, 0.1);
    EXPECT_NEAR(std::log2(a_error[k] / a_error[k + 1]), 2.0, 0.1);
    EXPECT_NEAR(std::log2(v_error[k] / v_error[k + 1]), 2.0, 0.1);
  }
}

}  // namespace
}  // namespace catena
