// SPDX-License-Identifier: MIT
// check_statics_match (catena/statics/statics_match.hpp): statics given to a solver must be the
// problem's. Each field changed alone is named; the problem's own statics passes; and every typed
// entry point and run_solver refuse another problem's statics before any work (issue 32: through
// Python the statics of a fairlead at (800, 300) gave frequencies 30 % off for one at (900, 300)).
#include "catena/statics/statics_match.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "catena/core/error.hpp"
#include "catena/solvers/asymptotic_solver.hpp"
#include "catena/solvers/fe_solver.hpp"
#include "catena/solvers/shooting_solver.hpp"
#include "catena/solvers/solver_registry.hpp"
#include "catena/statics/dimensionless_groups.hpp"
#include "catena/statics/problem_builders.hpp"
#include "solvers/common/solver_test_support.hpp"

namespace catena {
namespace {

// The mooring line, its fairlead at `b` (solver_test_support.hpp).
Problem mooring(Vec2 b = Vec2(900.0, 300.0)) { return testing::mooring_line(b); }

// The InvalidInput message of check_statics_match(problem, statics of `other`), or "" if none.
std::string refusal(const Problem& problem, const Problem& other) {
  try {
    check_statics_match(problem, solve_statics(other));
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(StaticsMatch, TheProblemsOwnStaticsPasses) {
  const Problem p = mooring();
  EXPECT_NO_THROW(check_statics_match(p, solve_statics(p)));
  Problem seabed = mooring();
  seabed.supports.a_m = Vec2(0.0, -50.0);
  seabed.seabed = Seabed{-50.0, 0.5};
  EXPECT_NO_THROW(check_statics_match(seabed, solve_statics(seabed)));
  const Problem taut = make_taut_inclined_problem(0.1, 30.0, 10.0, 1.0);
  EXPECT_NO_THROW(check_statics_match(taut, solve_statics(taut)));
}

TEST(StaticsMatch, EachFieldChangedAloneIsNamed) {
  const Problem p = mooring();
  const std::pair<std::function<void(Problem&)>, std::string> changes[] = {
      {[](Problem& q) { q.supports.b_m = Vec2(800.0, 300.0); }, "supports.b_m = (900, 300) m here"},
      {[](Problem& q) { q.supports.b_m.y() += 1e-6; }, "supports.b_m"},
      {[](Problem& q) { q.supports.a_m.x() += 1.0, q.supports.b_m.x() += 1.0; },
       "supports.a_m = (0, 0) m here, (1, 0) m"},
      {[](Problem& q) { q.cable.length_m = 1001.0; }, "cable.length_m = 1000 here, 1001"},
      {[](Problem& q) { q.cable.weight_n_per_m = 999.0; }, "cable.weight_n_per_m"},
      {[](Problem& q) { q.cable.axial_stiffness_n = 4e8; }, "cable.axial_stiffness_n"},
      {[](Problem& q) { q.cable.mass_kg_per_m = 121.0; }, "cable.mass_kg_per_m"},
      {[](Problem& q) { q.cable.added_mass_kg_per_m = 81.0; }, "cable.added_mass_kg_per_m"},
      {[](Problem& q) { q.cable.damping.axial_n_s = 1.0; }, "cable.damping.axial_n_s"},
      {[](Problem& q) {
         q.cable.drag = MorisonDrag{0.1, 1.2, 0.0};
       },
       "cable.drag.diameter_m"},
      {[](Problem& q) { q.seabed = Seabed{-10.0}; }, "seabed absent here, present in the statics"},
  };
  for (const auto& [change, field] : changes) {
    Problem other = p;
    change(other);
    const std::string message = refusal(p, other);
    EXPECT_NE(message.find(field), std::string::npos) << field << ": " << message;
    EXPECT_EQ(message.rfind("statics: solved for ", 0), 0u) << message;
  }
}

TEST(StaticsMatch, SeabedLineAndEndForcesAreCompared) {
  Problem seabed = mooring();
  seabed.supports.a_m = Vec2(0.0, -50.0);
  seabed.seabed = Seabed{-50.0, 0.5};
  Problem rougher = seabed;
  rougher.seabed->friction = 0.6;
  EXPECT_NE(refusal(seabed, rougher).find("seabed.friction = 0.5 here, 0.6"), std::string::npos);

  Problem line = mooring();
  line.line.segments = {{400.0, 1000.0, 5e8, 120.0}, {600.0, 60.0, 2e8, 8.0}};
  line.line.points = {{500.0, 1e3, 1e4}};
  Problem heavier = line;
  heavier.line.points[0].weight_n = 2e4;
  EXPECT_NE(refusal(line, heavier).find("line.points[0].weight_n"), std::string::npos);
  Problem longer = line;
  longer.line.segments[1].length_m = 601.0;
  EXPECT_NE(refusal(line, longer).find("line.segments[1].length_m"), std::string::npos);
  EXPECT_NE(refusal(line, mooring()).find("2 segment(s) here, 1"), std::string::npos);

  // Tension-specified problems: the statics is the end forces (another lambda^2 moves EA first).
  const Problem taut = make_taut_inclined_problem(0.1, 30.0, 10.0, 1.0);
  Problem pulled = taut;
  pulled.prescribed_forces->horizontal_n *= 1.0 + 1e-12;
  EXPECT_NE(refusal(pulled, taut).find("prescribed_forces.horizontal_n"), std::string::npos);
}

// The driver makes the check for every solver, through the typed entry points and run_solver.
TEST(StaticsMatch, EveryEntryPointRefusesAnotherProblemsStatics) {
  const Problem p = mooring();
  const StaticSolution other = solve_statics(mooring(Vec2(800.0, 300.0)));
  const DimensionlessGroups groups = compute_dimensionless_groups(p, solve_statics(p));
  SolveRequest request;
  request.inplane_modes = 1;
  EXPECT_THROW(solve_shooting(p, other, groups, request, {}), InvalidInput);
  EXPECT_THROW(solve_fe(p, other, groups, request, {}), InvalidInput);
  EXPECT_THROW(solve_asymptotic(p, other, groups, request, {}), InvalidInput);
  for (const SolverEntry& entry : solver_registry()) {
    EXPECT_THROW(run_solver(entry, SolveContext{p, other, groups, request}, {}), InvalidInput)
        << entry.name;
  }
}

}  // namespace
}  // namespace catena
