// SPDX-License-Identifier: MIT
// run_scene: statics, groups and request shared by the solvers, then the checks; the two kinds of
// scene error (bad input, numerical failure) and the options' validation.
#include "catena/verification/scene_runner.hpp"

#include <gtest/gtest.h>

#include "catena/core/error.hpp"
#include "catena/io/findings_reader.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/tolerance_reader.hpp"

namespace catena {
namespace {

Scene scene_from(const std::string& cable, const std::string& rest = "") {
  return parse_scene_text("[cable]\n" + cable + rest, "test.toml").front();
}

// A sagging 10 m elastic line that fe and shooting both solve.
const std::string kLine =
    "length = 10.0\nweight = 1.0\nEA = 1e6\nmass = 1.0\na = [0.0, 0.0]\nb = [8.0, 1.0]\n";

SceneRunOptions options_with_tables() {
  SceneRunOptions options;
  options.tolerances = builtin_tolerance_table();
  options.findings = builtin_findings_table();
  return options;
}

TEST(SceneRunner, SolvesStaticsSolversAndChecks) {
  SceneRunOptions options = options_with_tables();
  options.only_solvers = {"fe", "shooting"};
  const SceneResult result =
      run_scene(scene_from(kLine, "[request]\ninplane_modes = 3\n"), options);
  EXPECT_TRUE(result.error.empty()) << result.error;
  EXPECT_EQ(result.error_kind, SceneError::None);
  ASSERT_TRUE(result.statics);
  ASSERT_TRUE(result.groups);
  ASSERT_EQ(result.outputs.size(), 2u);
  EXPECT_EQ(result.outputs[0].summary.termination, Termination::Converged)
      << result.outputs[0].summary.message;
  EXPECT_EQ(result.outputs[0].solver, "fe");
  EXPECT_EQ(result.outputs[1].solver, "shooting");
  EXPECT_FALSE(result.checks.empty());
  EXPECT_EQ(result.failed_checks(), 0);
}

TEST(SceneRunner, UnreachableChordIsBadInput) {
  const SceneResult result = run_scene(
      scene_from(
          "length = 1.0\nweight = 1.0\nEA = \"inf\"\nmass = 1.0\na = [0.0, 0.0]\nb = [2.0, 0.0]\n"),
      options_with_tables());
  EXPECT_EQ(result.error_kind, SceneError::BadInput);
  EXPECT_NE(result.error.find("test.toml"), std::string::npos) << result.error;
  EXPECT_FALSE(result.statics);
  EXPECT_TRUE(result.outputs.empty());
}

TEST(SceneRunner, StaticsThatDoNotConvergeAreANumericalFailure) {
  // A heavy, very compliant line on a nearly vertical chord: Newton stalls near 1e-8 m closure.
  const SceneResult result =
      run_scene(scene_from("length = 1000.0\nweight = 1.0e6\nEA = 1.0e3\nmass = 1.0\na = [0.0, "
                           "0.0]\nb = [1.0, 999.0]\n"),
                options_with_tables());
  EXPECT_EQ(result.error_kind, SceneError::NumericalFailure);
  EXPECT_NE(result.error.find("did not converge"), std::string::npos) << result.error;
  EXPECT_FALSE(result.statics);
  EXPECT_TRUE(result.checks.empty());
}

TEST(SceneRunner, ChecksWithoutAToleranceTableAreRejectedBeforeAnyWork) {
  EXPECT_THROW(run_scene(scene_from(kLine), SceneRunOptions{}), InvalidInput);
  SceneRunOptions no_checks;
  no_checks.checks = false;
  no_checks.only_solvers = {"fe"};
  EXPECT_NO_THROW(run_scene(scene_from(kLine), no_checks));
}

TEST(SceneRunner, PerturbationChangesOnlyTheChosenFrequency) {
  SceneRunOptions options = options_with_tables();
  options.only_solvers = {"fe"};
  const Scene scene = scene_from(kLine, "[request]\ninplane_modes = 3\n");
  const SceneResult clean = run_scene(scene, options);
  options.perturbation = Perturbation{"fe", Plane::InPlane, 2, 1e-3};
  const SceneResult perturbed = run_scene(scene, options);
  ASSERT_TRUE(clean.outputs[0].inplane && perturbed.outputs[0].inplane);
  const auto& a = clean.outputs[0].inplane->modes;
  const auto& b = perturbed.outputs[0].inplane->modes;
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(a[0].omega_rad_s, b[0].omega_rad_s);
  EXPECT_DOUBLE_EQ(b[1].omega_rad_s, a[1].omega_rad_s * (1.0 + 1e-3));
  EXPECT_EQ(a[2].omega_rad_s, b[2].omega_rad_s);
  EXPECT_EQ(to_string(Verdict::SourceDiscrepancy), "SOURCE");
}

// The forced check's condition number needs the natural frequencies above the forcing: where no
// solver's output holds them, fe solves for them even when the scene did not run it, and they
// agree with shooting's to fe's accuracy.
TEST(SceneRunner, ForcedConditioningIsSolvedByFeWhenNoOutputHoldsTheModes) {
  SceneRunOptions options = options_with_tables();
  options.only_solvers = {"shooting"};
  const std::string forced =
      "[request]\ninplane_modes = 0\n[request.forced]\nend = \"b\"\ndirection = \"tangential\"\n"
      "amplitude = 0.01\nfrequencies = [3.0, 9.0]\n";
  const SceneResult result = run_scene(scene_from(kLine, forced), options);
  ASSERT_TRUE(result.error.empty()) << result.error;
  const ForcedConditioning& conditioning = result.forced_conditioning;
  EXPECT_EQ(conditioning.solver, "fe");
  EXPECT_NE(conditioning.note.find("solved for the condition number"), std::string::npos)
      << conditioning.note;
  ASSERT_GE(conditioning.omegas_rad_s.size(), 2u);
  EXPECT_GT(conditioning.omegas_rad_s.back(), 9.0);

  options.only_solvers = {"shooting"};
  const SceneResult modes = run_scene(scene_from(kLine, "[request]\ninplane_modes = 2\n"), options);
  ASSERT_TRUE(modes.outputs.at(0).inplane);
  for (std::size_t n = 0; n < 2; ++n)
    EXPECT_NEAR(conditioning.omegas_rad_s[n], modes.outputs[0].inplane->modes[n].omega_rad_s,
                1e-5 * conditioning.omegas_rad_s[n]);
}

}  // namespace
}  // namespace catena
