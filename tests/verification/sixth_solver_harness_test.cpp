// SPDX-License-Identifier: MIT
// A sixth exact solver joins the harness and the mutation score with no edit there: the taut
// string of tests/solvers/common/taut_string_solver.hpp, added by register_solver() at run time,
// is read from a scene's [solvers] table, run by run_scene, compared with fe and shooting by the
// frequency checks, and its mutations are counted among the exact solvers' (exact_with_witness),
// all because its registry entry says it is exact and states its accuracy target.
//
// The cable: a taut string (eps = 1e-6, lambda^2 = 1e-4), out of plane, where the string differs
// from the exact cable by the sag and static strain it ignores, ~1e-6. The test's own tolerance
// rule holds every pair to 1e-5; the string promises max_eps = 1e-5, so its frequencies are mutated
// by 10 x 1e-5 = 1e-4, which its comparisons with fe and shooting must catch.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "catena/io/scene_reader.hpp"
#include "catena/verification/mutation.hpp"
#include "solvers/common/taut_string_solver.hpp"

namespace catena {
namespace {

// Registers the string once per test executable (the registry is process-wide).
void register_string_once() {
  static const bool registered = [] {
    register_solver(testing::make_string_entry());
    return true;
  }();
  (void)registered;
}

ToleranceRule rule(const std::string& check, double max) {
  ToleranceRule r;
  r.check = check;
  r.compare = {"*", "*"};
  r.max = max;
  r.reason = "test rule: the string ignores sag and strain, ~1e-6 here";
  return r;
}

SceneRunOptions options() {
  SceneRunOptions run;
  run.tolerances = ToleranceTable({rule("frequency", 1e-5)});
  return run;
}

SceneResult solved_string_scene(const SceneRunOptions& run) {
  const Scene scene = parse_scene_text(
                          "[taut_inclined]\neps = 1e-6\nphi_deg = 0.0\nlambda2 = 1e-4\n"
                          "[request]\ninplane_modes = 0\noutofplane_modes = 3\n"
                          "[solvers]\nfe = {}\nshooting = {}\nstring = { max_eps = 1e-5 }\n",
                          "string.toml")
                          .front();
  return run_scene(scene, run);
}

bool names(const std::string& compare, const std::string& a, const std::string& b) {
  return compare == a + " vs " + b || compare == b + " vs " + a;
}

TEST(SixthSolverHarness, ARegisteredSolverRunsInEveryScene) {
  register_string_once();
  ASSERT_NE(find_solver("string"), nullptr);
  EXPECT_TRUE(is_exact_solver("string"));
  // A scene that names no solver runs every registered one, the sixth included.
  const std::vector<std::string> all = Scene{}.solver_names();
  EXPECT_EQ(all.size(), 6u);
  EXPECT_EQ(all.back(), "string");
  // The five keep their roles and order; the string (1e-3 at its defaults) ranks after fe (1e-6)
  // and certifies nothing.
  EXPECT_EQ(exact_solvers_by_accuracy(),
            (std::vector<std::string>{"frobenius", "shooting", "fe", "string"}));
  EXPECT_EQ(reference_solvers(), (std::vector<std::string>{"shooting", "fe"}));
  EXPECT_THROW(register_solver(testing::make_string_entry()), InvalidInput);  // name taken
}

TEST(SixthSolverHarness, TheHarnessComparesItWithTheOtherSolvers) {
  register_string_once();
  const SceneResult result = solved_string_scene(options());
  ASSERT_TRUE(result.error.empty()) << result.error;
  ASSERT_EQ(result.outputs.size(), 3u);
  EXPECT_EQ(result.outputs.back().solver, "string");  // registry order
  EXPECT_EQ(result.failed_checks(), 0);
  for (const char* other : {"fe", "shooting"}) {
    const auto compared =
        std::count_if(result.checks.begin(), result.checks.end(), [&](const CheckResult& check) {
          return check.check == "frequency" && names(check.compare, "string", other) &&
                 check.verdict == Verdict::Pass;
        });
    EXPECT_EQ(compared, 3) << "string vs " << other;
  }
}

TEST(SixthSolverHarness, TheMutationScoreCountsItAmongTheExactSolvers) {
  register_string_once();
  const SceneRunOptions run = options();
  const SceneResult result = solved_string_scene(run);
  ASSERT_EQ(result.failed_checks(), 0);
  // Its target comes from its entry, with the scene's knobs.
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("string", {{"max_eps", 1e-5}}, Mode{}), 1e-5);
  MutationRun string_only;
  for (const MutationOutcome& outcome : mutate_scene(result, run)) {
    if (outcome.solver == "string") string_only.outcomes.push_back(outcome);
  }
  ASSERT_EQ(string_only.outcomes.size(), 3u);  // three out-of-plane frequencies
  for (const MutationOutcome& outcome : string_only.outcomes) {
    EXPECT_EQ(outcome.quantity, MutatedQuantity::Frequency);
    EXPECT_DOUBLE_EQ(outcome.size, 1e-4);
    EXPECT_TRUE(outcome.exact_witness) << "mode " << outcome.mode;
    EXPECT_TRUE(outcome.caught) << "mode " << outcome.mode;
  }
  const MutationTally tally = string_only.exact_with_witness();
  EXPECT_EQ(tally.made, 3);
  EXPECT_EQ(tally.caught, 3);
}

}  // namespace
}  // namespace catena
