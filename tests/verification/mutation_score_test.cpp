// SPDX-License-Identifier: MIT
// The mutation score of the real harness (builtin tolerance and findings tables) on six scenes
// from six families: every exact solver's mutation must be caught where another exact solver ran
// (issue 12's target), and every uncaught one is named in the failure message.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "catena/io/findings_reader.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "catena/verification/mutation.hpp"

namespace catena {
namespace {

const char* const kScenes[] = {
    "analytic/taut-string.toml",         "gale/gale-b-3-hb0.25-sag0.70.toml",
    "gale/gale-c-2-hb0.00-sag0.70.toml", "grinfogel/grinfogel-eps0.18-phi23.46-lambda2-38.toml",
    "physical/mooring-line-900m.toml",   "studies/inclined-grid-eps0.05-phi45.0.toml"};

MutationRun subset_run() {
  SceneRunOptions options;
  options.tolerances = builtin_tolerance_table();
  options.findings = builtin_findings_table();
  std::vector<Scene> scenes;
  for (const char* file : kScenes) {
    scenes.push_back(
        read_scene_file(std::filesystem::path(CATENA_SOURCE_DIR) / "verification/scenes" / file)
            .front());
  }
  return run_mutations(run_scenes(scenes, 0, options), 0, options);
}

std::string uncaught_list(const MutationRun& run, bool exact_with_witness_only) {
  std::string text;
  for (const auto& o : run.outcomes) {
    if (o.caught || (exact_with_witness_only && !(is_exact_solver(o.solver) && o.exact_witness)))
      continue;
    text += fmt::format("  {} {} {} {} mode {} (size {:.1e})\n", o.scene, o.solver,
                        to_string(o.quantity), o.plane, o.mode, o.size);
  }
  return text;
}

TEST(MutationScore, EveryMutationIsCountedOnceAndEveryUncaughtOneIsNamed) {
  const MutationRun run = subset_run();
  int made = 0, caught = 0;
  for (const auto& [what, tally] : run.tallies()) made += tally.made, caught += tally.caught;
  EXPECT_EQ(made, static_cast<int>(run.outcomes.size()));
  const MutationTally exact = run.exact_with_witness();
  EXPECT_GT(exact.made, 0);
  std::cout << fmt::format(
      "exact solvers with an exact witness: {} of {} caught; all solvers: {} of {}\n", exact.caught,
      exact.made, caught, made);
  std::cout << "uncaught:\n" << uncaught_list(run, false);
}

// Issue 12's target on these six scenes: every exact-solver mutation is caught where another exact
// solver ran (152 of 152 since fe's forced solve is refined against the unrounded chain; 101, 142,
// 143 and 148 in earlier sessions). On the whole suite the uncaught ones are listed in
// docs/explanation/mutation.md.
TEST(MutationScore, ExactSolversCatchEveryMutationWhereTwoRan) {
  const MutationRun run = subset_run();
  const MutationTally exact = run.exact_with_witness();
  EXPECT_GT(exact.made, 100);
  EXPECT_EQ(exact.caught, exact.made) << "uncaught:\n" << uncaught_list(run, true);
}

// The part of it a check can always be asked for: every change larger than the mutated value's
// own error estimate (beyond what its solver claims). A change within it is within what no check
// that honours the estimates can see (docs/explanation/mutation.md, "Two counts").
TEST(MutationScore, ExactSolversCatchEveryChangeBeyondTheirOwnEstimateWhereTwoRan) {
  const MutationRun run = subset_run();
  const MutationTally beyond = run.exact_beyond_estimate();
  EXPECT_GT(beyond.made, 100);
  std::string uncaught;
  for (const auto& o : run.outcomes) {
    if (!o.caught && is_exact_solver(o.solver) && o.exact_witness && o.size > o.estimate)
      uncaught += fmt::format("  {} {} {} {} mode {} (size {:.1e}, own estimate {:.1e})\n", o.scene,
                              o.solver, to_string(o.quantity), o.plane, o.mode, o.size, o.estimate);
  }
  EXPECT_EQ(beyond.caught, beyond.made) << "uncaught:\n" << uncaught;
}

}  // namespace
}  // namespace catena
