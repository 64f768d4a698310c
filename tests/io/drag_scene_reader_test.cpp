// SPDX-License-Identifier: MIT
// The scene keys of issue 30 (docs/reference/scene-format.md, "Drag and dynamic tension in
// waves"): what the reader builds from [cable]/[[line.segments]] drag keys, [environment] and
// [request.motion] (regular, a spectrum table, JONSWAP with an RAO per wave amplitude or height),
// and each bad value refused naming its table and key. Expected values are the scene's own
// numbers and the documented defaults.
#include <gtest/gtest.h>

#include <string>

#include "catena/core/error.hpp"
#include "catena/io/scene_reader.hpp"

namespace catena {
namespace {

const std::string kCable = R"(
[cable]
length = 1000.0
weight = 1000.0
EA = 5.0e8
mass = 120.0
added_mass = 80.0
a = [0.0, 0.0]
b = [900.0, 300.0]
)";

Scene read_one(const std::string& text) {
  const auto scenes = parse_scene_text(text, "w.toml");
  EXPECT_EQ(scenes.size(), 1u);
  return scenes.at(0);
}

// The message of the error `text` raises (empty when none).
std::string error_of(const std::string& text) {
  try {
    parse_scene_text(text, "w.toml");
  } catch (const Error& error) {
    return error.what();
  }
  return {};
}

TEST(DragScene, CableAndSegmentKeysSetTheDragAndTangentialAddedMass) {
  const Problem cable = read_one(kCable +
                                 "diameter = 0.12\ndrag_normal = 2.4\ndrag_tangential = 1.15\n"
                                 "added_mass_tangential = 5.0\n")
                            .problem;
  EXPECT_EQ(cable.cable.drag.diameter_m, 0.12);
  EXPECT_EQ(cable.cable.drag.normal, 2.4);
  EXPECT_EQ(cable.cable.drag.tangential, 1.15);
  EXPECT_EQ(cable.cable.added_mass_tangential_kg_per_m, 5.0);
  EXPECT_TRUE(cable.has_drag());
  EXPECT_TRUE(cable.has_tangential_added_mass());
  const Problem plain = read_one(kCable).problem;
  EXPECT_FALSE(plain.has_drag()) << "drag defaults to none";
  EXPECT_FALSE(plain.has_tangential_added_mass());

  const Problem line = read_one(R"(
[line]
a = [0.0, -100.0]
b = [400.0, 0.0]
[[line.segments]]
length = 300.0
weight = 500.0
EA = 1e8
mass = 60.0
diameter = 0.1
drag_normal = 1.2
[[line.segments]]
length = 200.0
weight = 200.0
EA = 1e8
mass = 30.0
added_mass_tangential = 2.0
)")
                           .problem;
  ASSERT_EQ(line.line.segments.size(), 2u);
  EXPECT_EQ(line.line.segments[0].drag.diameter_m, 0.1);
  EXPECT_EQ(line.line.segments[0].drag.normal, 1.2);
  EXPECT_EQ(line.line.segments[0].drag.tangential, 0.0);
  EXPECT_TRUE(line.line.segments[1].drag.is_zero());
  EXPECT_EQ(line.line.segments[1].added_mass_tangential_kg_per_m, 2.0);
}

// One segment of positive weight is read as the uniform cable: its drag must come with it.
TEST(DragScene, AOneSegmentLineKeepsItsDragAsTheCable) {
  const Problem problem = read_one(R"(
[line]
a = [0.0, 0.0]
b = [900.0, 300.0]
[[line.segments]]
length = 1000.0
weight = 1000.0
EA = 5.0e8
mass = 120.0
diameter = 0.2
drag_normal = 1.0
drag_tangential = 0.3
added_mass_tangential = 4.0
)")
                              .problem;
  ASSERT_TRUE(problem.is_uniform());
  EXPECT_EQ(problem.cable.drag.diameter_m, 0.2);
  EXPECT_EQ(problem.cable.drag.normal, 1.0);
  EXPECT_EQ(problem.cable.drag.tangential, 0.3);
  EXPECT_EQ(problem.cable.added_mass_tangential_kg_per_m, 4.0);
}

TEST(DragScene, EnvironmentDefaultsAndKeys) {
  const Environment defaults = read_one(kCable).problem.environment;
  EXPECT_EQ(defaults.water_density_kg_per_m3, 1025.0);
  EXPECT_EQ(defaults.gravity_m_per_s2, 9.80665);
  const Environment water =
      read_one(kCable + "[environment]\nwater_density = 1020.0\ngravity = 9.81\n")
          .problem.environment;
  EXPECT_EQ(water.water_density_kg_per_m3, 1020.0);
  EXPECT_EQ(water.gravity_m_per_s2, 9.81);
}

TEST(MotionScene, RegularMotionIsReadInSiUnits) {
  const Scene scene = read_one(kCable + R"(
[request.motion]
direction = [1.0, 0.5]
amplitude = 2.0
periods = [8.0, 10.0, 12.0]
tolerance = 1e-9
max_iterations = 50
)");
  ASSERT_TRUE(scene.request.motion);
  const MotionRequest& m = *scene.request.motion;
  EXPECT_EQ(m.direction, ForcingDirection::GivenVector);
  EXPECT_EQ(m.vector, Vec2(1.0, 0.5));
  EXPECT_EQ(m.amplitude_m, 2.0);
  EXPECT_EQ(m.periods_s, (std::vector<double>{8.0, 10.0, 12.0}));
  EXPECT_FALSE(m.is_irregular());
  EXPECT_EQ(m.tolerance, 1e-9);
  EXPECT_EQ(m.max_iterations, 50);
  const Scene out_of_plane = read_one(
      kCable +
      "[request.motion]\ndirection = \"out_of_plane\"\namplitude = 1.0\nperiods = [9.0]\n");
  EXPECT_EQ(out_of_plane.request.motion->direction, ForcingDirection::OutOfPlane);
  EXPECT_FALSE(read_one(kCable).request.motion) << "no [request.motion]: no dynamic tension";
}

TEST(MotionScene, IrregularMotionFromATableOrJonswapWithAnRao) {
  const Scene table = read_one(kCable + R"(
[request.motion]
spectrum = { omega = [0.2, 0.5, 1.0], density = [0.0, 1.5, 0.1] }
duration = 3600.0
)");
  const MotionRequest& m = *table.request.motion;
  ASSERT_TRUE(m.spectrum);
  EXPECT_TRUE(m.is_irregular());
  EXPECT_EQ(m.spectrum->omega_rad_s, (std::vector<double>{0.2, 0.5, 1.0}));
  EXPECT_EQ(m.spectrum->density_m2_s_per_rad, (std::vector<double>{0.0, 1.5, 0.1}));
  EXPECT_EQ(m.duration_s, 3600.0);
  EXPECT_EQ(m.frequencies, 200) << "the default JONSWAP grid";

  const std::string jonswap = kCable + R"(
[request.motion]
direction = "out_of_plane"
jonswap = { hs = 6.0, tp = 12.0, gamma = 3.3 }
frequencies = 300
rao = { omega = [0.2, 0.6, 1.2], amplitude = [1.0, 0.8, 0.1], phase_deg = [0.0, -30.0, -90.0])";
  const MotionRequest amplitude = *read_one(jonswap + " }\n").request.motion;
  ASSERT_TRUE(amplitude.jonswap && amplitude.rao);
  EXPECT_EQ(amplitude.jonswap->hs_m, 6.0);
  EXPECT_EQ(amplitude.jonswap->tp_s, 12.0);
  EXPECT_EQ(amplitude.jonswap->gamma, 3.3);
  EXPECT_EQ(amplitude.frequencies, 300);
  EXPECT_EQ(amplitude.rao->phase_deg, (std::vector<double>{0.0, -30.0, -90.0}));
  EXPECT_FALSE(amplitude.rao->per_wave_height) << "an RAO is per unit wave amplitude by default";
  const Scene height = read_one(jonswap + ", per = \"wave_height\" }\n");
  ASSERT_TRUE(height.request.motion && height.request.motion->rao);
  EXPECT_TRUE(height.request.motion->rao->per_wave_height);
}

// Each bad value: the message names the table and key (the reader's) or the request field
// (MotionRequest::validate()'s), and the rule.
TEST(MotionScene, BadValuesAreRefusedNamingTheField) {
  const std::string regular = "[request.motion]\namplitude = 1.0\n";
  const std::string rao = "\nrao = { omega = [0.2, 0.6], amplitude = [1.0, 0.5] }";
  const std::pair<std::string, std::string> cases[] = {
      {kCable + "diameter = 0.0\n", "[cable].diameter = 0: must be finite and > 0"},
      {kCable + "diameter = -0.1\n", "[cable].diameter = -0.1"},
      {kCable + "diameter = 0.1\ndrag_normal = -1.0\n", "[cable].drag_normal = -1"},
      {kCable + "drag_normal = 1.0\n", "cable.drag_normal = 1: a drag coefficient needs"},
      {kCable + "diameter = 0.1\ndrag_tangential = inf\n", "[cable].drag_tangential = inf"},
      {kCable + "added_mass_tangential = -2.0\n", "[cable].added_mass_tangential = -2"},
      {kCable + "[environment]\nwater_density = 0.0\n", "[environment].water_density = 0"},
      {kCable + "[environment]\ngravity = -9.8\n", "[environment].gravity = -9.8"},
      {kCable + "[environment]\nsalinity = 35.0\n", "[environment].salinity: unknown key"},
      {kCable + regular + "periods = [8.0, 0.0]\n", "periods: period 1 = 0 must be > 0"},
      {kCable + regular + "periods = [-8.0]\n", "periods: period 0 = -8 must be > 0"},
      {kCable + "[request.motion]\namplitude = -1.0\nperiods = [8.0]\n",
       "[request.motion].amplitude = -1"},
      {kCable + regular + "periods = [8.0]\nwave = 3.0\n", "[request.motion].wave: unknown key"},
      {kCable + regular + "periods = [8.0]\ndirection = \"heave\"\n",
       "[request.motion].direction = \"heave\""},
      {kCable + "[request.motion]\nspectrum = { omega = [0.2, 0.5], density = [1.0, -0.5] }\n",
       "request.motion.spectrum.density[1] = -0.5: must be >= 0"},
      {kCable + "[request.motion]\nspectrum = { omega = [0.2, 0.5], density = [1.0] }\n",
       "request.motion.spectrum.density: 1 values, but the frequency column has 2"},
      {kCable + "[request.motion]\njonswap = { hs = 0.0, tp = 10.0 }" + rao + "\n",
       "[request.motion.jonswap].hs = 0: must be finite and > 0"},
      {kCable + "[request.motion]\njonswap = { hs = -2.0, tp = 10.0 }" + rao + "\n",
       "[request.motion.jonswap].hs = -2"},
      {kCable + "[request.motion]\njonswap = { hs = 2.0, tp = 10.0 }\nrao = { omega = [0.6, 0.2], "
                "amplitude = [1.0, 0.5] }\n",
       "request.motion.rao.omega[1] = 0.2: the frequencies must be strictly increasing"},
      {kCable + "[request.motion]\njonswap = { hs = 2.0, tp = 10.0 }\nrao = { omega = [0.2, nan], "
                "amplitude = [1.0, 0.5] }\n",
       "[request.motion.rao].omega: entry nan is not finite"},
      {kCable + "[request.motion]\njonswap = { hs = 2.0, tp = 10.0 }\nrao = { omega = [0.2, 0.6], "
                "amplitude = [1.0, 0.5], phase_deg = [0.0] }\n",
       "request.motion.rao.phase_deg: 1 values, but the frequency column has 2"},
      {kCable + "[request.motion]\njonswap = { hs = 2.0, tp = 10.0 }" + rao +
           "\nspectrum = { omega = [0.2, 0.5], density = [1.0, 0.5] }\n",
       "give either spectrum or jonswap (with rao), not both"},
      {kCable + "[request.motion]\njonswap = { hs = 2.0, tp = 10.0 }" +
           "\nrao = { omega = [0.2, 0.6], amplitude = [1.0, 0.5], per = \"metre\" }\n",
       "[request.motion.rao].per = \"metre\""},
      {kCable + "[request.motion]\njonswap = { hs = 2.0, tp = 10.0 }\n",
       "a wave spectrum needs the fairlead's motion RAO"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string message = error_of(text);
    EXPECT_NE(message.find(expected), std::string::npos)
        << "expected \"" << expected << "\" in \"" << message << "\"";
  }
}

}  // namespace
}  // namespace catena
