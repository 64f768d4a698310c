// SPDX-License-Identifier: MIT
// Mutation testing of the harness (docs/explanation/mutation.md): a frequency made wrong beyond its
// check's tolerance is caught by a frequency check, one within it is reported uncaught, a shape mix
// is caught by the shape checks, and the accuracy targets follow each solver's knobs.
#include "catena/verification/mutation.hpp"

#include <gtest/gtest.h>

#include "catena/io/scene_reader.hpp"
#include "verification/internal/mode_mix.hpp"

namespace catena {
namespace {

ToleranceRule rule(const std::string& check, double max) {
  ToleranceRule r;
  r.check = check;
  r.compare = {"*", "*"};
  r.max = max;
  r.reason = "test rule";
  return r;
}

// A taut inclined cable solved by fe and shooting, with shapes, under a frequency rule
// `frequency_max`.
SceneRunOptions options_with(double frequency_max) {
  SceneRunOptions options;
  options.tolerances =
      ToleranceTable({rule("frequency", frequency_max), rule("mac", 1e-6), rule("shape", 1e-3)});
  options.only_solvers = {"fe", "shooting"};
  return options;
}

SceneResult solved(const SceneRunOptions& options) {
  const Scene scene = parse_scene_text(
                          "[taut_inclined]\neps = 0.1\nphi_deg = 30.0\nlambda2 = "
                          "10.0\n[request]\ninplane_modes = 3\nshapes = true\n",
                          "mutation.toml")
                          .front();
  return run_scene(scene, options);
}

std::vector<MutationOutcome> of(const std::vector<MutationOutcome>& all,
                                const std::string& solver,
                                MutatedQuantity quantity) {
  std::vector<MutationOutcome> out;
  for (const auto& o : all) {
    if (o.solver == solver && o.quantity == quantity) out.push_back(o);
  }
  return out;
}

TEST(Mutation, AFrequencyMadeWrongBeyondItsToleranceIsCaughtByAFrequencyCheck) {
  const SceneRunOptions options = options_with(1e-8);
  const SceneResult result = solved(options);
  ASSERT_EQ(result.failed_checks(), 0);
  // fe's target is 1e-6 (its entry's accuracy_target without `tolerance`): its frequencies move
  // by 1e-5, far beyond the 1e-8 rule.
  const auto fe = of(mutate_scene(result, options), "fe", MutatedQuantity::Frequency);
  ASSERT_EQ(fe.size(), 3u);
  for (const auto& o : fe) {
    EXPECT_TRUE(o.caught) << "mode " << o.mode;
    EXPECT_DOUBLE_EQ(o.size, 1e-5);
    EXPECT_TRUE(o.exact_witness);
    EXPECT_EQ(o.caught_by, "frequency fe vs shooting in-plane mode " + std::to_string(o.mode));
    // The outcome keeps the mutated value's own estimate, from before the mutation.
    for (const auto& output : result.outputs) {
      if (output.solver == "fe") {
        EXPECT_DOUBLE_EQ(
            o.estimate,
            output.inplane->modes[static_cast<std::size_t>(o.mode - 1)].relative_error_estimate);
      }
    }
  }
}

TEST(Mutation, AFrequencyMadeWrongWithinItsToleranceIsReportedUncaught) {
  const SceneRunOptions options = options_with(1e-7);
  const SceneResult result = solved(options);
  // shooting's target is 10 rtol + root_tolerance, 1.1e-9: a 1.1e-8 change hides inside the 1e-7
  // rule.
  const auto shooting = of(mutate_scene(result, options), "shooting", MutatedQuantity::Frequency);
  ASSERT_EQ(shooting.size(), 3u);
  for (const auto& o : shooting) {
    EXPECT_FALSE(o.caught) << "mode " << o.mode;
    EXPECT_TRUE(o.caught_by.empty());
    EXPECT_DOUBLE_EQ(o.size, kFrequencyMutationFactor * (10 * 1e-10 + 1e-10));
  }
  MutationRun run;
  run.outcomes = mutate_scene(result, options);
  const auto tallies = run.tallies();
  const MutationTally tally = tallies.at({"shooting", "", "frequency"});
  EXPECT_EQ(tally.made, 3);
  EXPECT_EQ(tally.caught, 0);
  EXPECT_LT(run.exact_with_witness().caught, run.exact_with_witness().made);
  // shooting claims 1.1e-9 (its estimate's floor): a 1.1e-8 change is beyond it, so it counts
  // against the score of changes beyond the solvers' own estimates too.
  for (const auto& o : shooting) EXPECT_GT(o.size, o.estimate) << "mode " << o.mode;
  EXPECT_LT(run.exact_beyond_estimate().caught, run.exact_beyond_estimate().made);
}

TEST(Mutation, AModeMixIsCaughtByTheShapeChecks) {
  const SceneRunOptions options = options_with(1e-8);
  const auto shapes = of(mutate_scene(solved(options), options), "fe", MutatedQuantity::Shape);
  ASSERT_EQ(shapes.size(), 3u);
  for (const auto& o : shapes) {
    EXPECT_TRUE(o.caught) << "mode " << o.mode;
    EXPECT_NEAR(o.size, 10 * 1e-6, 1e-7);  // 1 - MAC against the unmutated shape: 10x the MAC rule
    EXPECT_EQ(o.caught_by.rfind("mac fe vs shooting", 0), 0u) << o.caught_by;
  }
}

TEST(Mutation, NothingIsRecordedForAnUnsolvedScene) {
  SceneResult failed;
  failed.error = "no statics";
  EXPECT_TRUE(mutate_scene(failed, options_with(1e-8)).empty());
}

// The targets are the solvers' own (SolverEntry::accuracy_target, the function their summaries
// use; tests/solvers/common/solver_registry_test.cpp checks the two agree): the values below are
// the documented formulas (docs/reference/verdicts.md, "Declared misses").
TEST(Mutation, AccuracyTargetsFollowEachSolversKnobs) {
  Mode mode;
  mode.relative_error_estimate = 3e-4;
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("shooting", {}, mode), 10 * 1e-10 + 1e-10);
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("shooting", {{"rtol", 1e-8}}, mode), 10 * 1e-8 + 1e-8);
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("frobenius", {}, mode), 10 * 1e-12);
  // Below 1e-14 the solver's floor holds (10 x 1e-14): the harness's old copy, 10 x tolerance,
  // had drifted from it.
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("frobenius", {{"tolerance", 1e-15}}, mode), 1e-13);
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("fe", {}, mode), 1e-6);
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("fe", {{"tolerance", 1e-7}}, mode), 1e-7);
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("asymptotic", {}, mode), 3e-4);
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("airy", {}, mode), 3e-4);
  mode.relative_error_estimate = -1.0;  // no estimate: no target, no mutation
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("airy", {}, mode), 0.0);
  EXPECT_DOUBLE_EQ(frequency_accuracy_target("galerkin", {}, mode), 0.0);  // not registered
}

TEST(ModeMix, TheMixReachesTheAskedDropOfMacAndKeepsTheNormalisation) {
  Mode a, b;
  a.s_m = b.s_m = Vector::LinSpaced(5, 0.0, 1.0);
  a.u = b.u = Vector::Zero(5);
  a.w = Vector::LinSpaced(5, 0.0, 1.0);
  b.w = (Vector(5) << 0.0, 1.0, 0.0, -1.0, 0.0).finished();
  a.normalised_by = "w";
  const Vector p = internal::stacked_shape(a, Plane::InPlane);
  const auto delta =
      internal::mix_for_mac_drop(p, internal::stacked_shape(b, Plane::InPlane), 1e-4);
  ASSERT_TRUE(delta);
  internal::mix_modes(a, b, *delta);
  EXPECT_NEAR(internal::one_minus_mac(p, internal::stacked_shape(a, Plane::InPlane)), 1e-4, 1e-10);
  EXPECT_DOUBLE_EQ(a.w.cwiseAbs().maxCoeff(), 1.0);
  // A neighbour parallel to the shape cannot lower the MAC.
  EXPECT_FALSE(internal::mix_for_mac_drop(p, 2.0 * p, 1e-4));
}

}  // namespace
}  // namespace catena
