// SPDX-License-Identifier: MIT
// catena check on another program's dynamic tension at the scene level
// (include/catena/verification/scene_tension_check.hpp) on the repository's mooring line
// (verification/scenes/physical/mooring-line-900m.toml, L = 1000 m) with a motion request set here:
// the reference scene asks exactly the excitation compared, bad requests are refused before any
// solve, and a run in which no solver computes the dynamic tension says so instead of comparing.
#include "catena/verification/scene_tension_check.hpp"

#include <gtest/gtest.h>

#include "catena/core/error.hpp"
#include "catena/io/scene_reader.hpp"

namespace catena {
namespace {

Scene mooring_line(bool irregular) {
  Scene scene = read_scene_file(std::string(CATENA_SOURCE_DIR) +
                                "/verification/scenes/physical/mooring-line-900m.toml")
                    .front();
  MotionRequest motion;
  motion.vector = Vec2(1.0, 0.0);
  if (irregular) {
    motion.spectrum = SpectrumTable{{0.2, 0.6, 1.0}, {0.5, 1.0, 0.2}};
  } else {
    motion.amplitude_m = 2.0;
    motion.periods_s = {8.0, 12.0};
  }
  scene.request.motion = motion;
  return scene;
}

ExternalTension fairlead_only(TensionQuantity quantity, std::optional<double> period) {
  ExternalTension tension;
  tension.quantity = quantity;
  tension.period_s = period;
  tension.origin = "other.csv";
  ExternalTensionStation station;
  station.s_m = 1000.0;
  station.tension_n = 1e5;
  station.origin = "other.csv row 1";
  tension.stations.push_back(station);
  return tension;
}

void expect_refused(const Scene& scene, const ExternalTension& tension, const std::string& part) {
  try {
    tension_reference_scene(scene, tension);
    ADD_FAILURE() << "no error, expected one with " << part;
  } catch (const InvalidInput& error) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
  }
}

TEST(SceneTensionCheck, ReferenceSceneAsksExactlyTheExcitationCompared) {
  const Scene scene =
      tension_reference_scene(mooring_line(false), fairlead_only(TensionQuantity::Amplitude, 12.0));
  ASSERT_TRUE(scene.request.motion.has_value());
  EXPECT_EQ(scene.request.motion->periods_s, std::vector<double>{12.0});
  EXPECT_EQ(scene.request.inplane_modes, 0);
  EXPECT_EQ(scene.request.outofplane_modes, 0);
  EXPECT_FALSE(scene.request.forced.has_value());
  EXPECT_EQ(scene.solvers.size(), 2u);
  EXPECT_EQ(scene.solvers.count("shooting"), 1u);
  EXPECT_EQ(scene.solvers.count("fe"), 1u);
}

TEST(SceneTensionCheck, RequestsThatDoNotFitTheFileAreRefused) {
  Scene none = mooring_line(false);
  none.request.motion.reset();
  expect_refused(none, fairlead_only(TensionQuantity::Amplitude, 8.0), "no [request.motion]");
  expect_refused(mooring_line(false), fairlead_only(TensionQuantity::Amplitude, {}),
                 "asks 2 periods; give the one compared in a period_s column");
  expect_refused(mooring_line(false), fairlead_only(TensionQuantity::Amplitude, 9.0),
                 "column 'period_s': 9 s is not a period");
  expect_refused(mooring_line(false), fairlead_only(TensionQuantity::StandardDeviation, {}),
                 "column 'tension_std_n': the scene's [request.motion] is regular");
  expect_refused(mooring_line(true), fairlead_only(TensionQuantity::Amplitude, {}),
                 "is irregular; give tension_std_n");
}

TEST(SceneTensionCheck, StationsOutsideTheLineAreRefusedBeforeTheSolve) {
  ExternalTension tension = fairlead_only(TensionQuantity::StandardDeviation, {});
  tension.stations.front().s_m = 1000.5;
  EXPECT_THROW(check_scene_tension(tension, mooring_line(true)), InvalidInput);
}

TEST(SceneTensionCheck, ARunWithoutADynamicTensionSaysSoAndComparesNothing) {
  const SceneTensionCheck checked = check_scene_tension(
      fairlead_only(TensionQuantity::StandardDeviation, {}), mooring_line(true));
  if (checked.check) {
    // Once a reference solver computes the dynamic tension, the comparison is made instead.
    EXPECT_TRUE(checked.check->reference.solver == "shooting" ||
                checked.check->reference.solver == "fe");
    EXPECT_TRUE(checked.error.empty());
  } else {
    EXPECT_NE(checked.error.find("no Catena solver computed the dynamic tension"),
              std::string::npos)
        << checked.error;
    // Both reference solvers ran and each says why it has no dynamic tension.
    EXPECT_NE(checked.error.find("shooting: did not compute the dynamic tension"),
              std::string::npos)
        << checked.error;
    EXPECT_NE(checked.error.find("fe: did not compute the dynamic tension"), std::string::npos)
        << checked.error;
  }
}

}  // namespace
}  // namespace catena
