// SPDX-License-Identifier: MIT
// Reading `[line]` scenes and statics-only scenes (docs/reference/scene-format.md, "General lines",
// "Statics-only scenes"). Compared: what the reader builds with what the text says; a one-segment
// line with the [cable] of the same values; every bad line input names its entry and field.
#include <gtest/gtest.h>

#include <string>

#include "catena/core/error.hpp"
#include "catena/io/scene_reader.hpp"
#include "test_utils.hpp"

namespace catena {
namespace {

const std::string kSegment = R"(
[[line.segments]]
length = 250.0
weight = 1400.0
EA = 7.5e8
mass = 160.0
added_mass = 25.0
)";

const std::string kLine = R"(
[line]
a = [0.0, -300.0]
b = [800.0, 0.0]
)" + kSegment + R"(
[[line.segments]]
length = 600.0
weight = -60.0
EA = "inf"
mass = 8.0
[[line.points]]
s = 250.0
mass = 20000.0
weight = 1.5e5
added_mass_normal = 300.0
)";

Scene parse_one(const std::string& text) {
  const auto scenes = parse_scene_text(text, "line.toml");
  EXPECT_EQ(scenes.size(), 1u);
  return scenes.front();
}

TEST(LineSceneReader, ReadsSegmentsAndPointsInOrder) {
  const Scene scene = parse_one(kLine + "[request]\ninplane_modes = 0\n");
  const Problem& p = scene.problem;
  ASSERT_FALSE(p.is_uniform());
  ASSERT_EQ(p.line.segments.size(), 2u);
  EXPECT_EQ(p.line.segments[0].length_m, 250.0);
  EXPECT_EQ(p.line.segments[0].added_mass_kg_per_m, 25.0);
  EXPECT_EQ(p.line.segments[1].weight_n_per_m, -60.0);
  EXPECT_TRUE(p.line.segments[1].is_inextensible());
  EXPECT_EQ(p.line.segments[1].added_mass_kg_per_m, 0.0);
  ASSERT_EQ(p.line.points.size(), 1u);
  EXPECT_EQ(p.line.points[0].s_m, 250.0);
  EXPECT_EQ(p.line.points[0].weight_n, 1.5e5);
  EXPECT_EQ(p.line.points[0].added_mass_kg, 0.0);
  EXPECT_EQ(p.line.points[0].normal_added_mass_kg(), 300.0);
  EXPECT_EQ(p.line.points[0].tangential_added_mass_kg(), 0.0);
  EXPECT_EQ(p.length_m(), 850.0);
  EXPECT_EQ(p.supports.b_m, Vec2(800.0, 0.0));
}

TEST(LineSceneReader, OneSegmentLineIsTheUniformCable) {
  const Scene scene = parse_one("[line]\na = [0.0, -300.0]\nb = [200.0, 0.0]\n" + kSegment);
  const Problem& p = scene.problem;
  ASSERT_TRUE(p.is_uniform());
  EXPECT_EQ(p.cable.length_m, 250.0);
  EXPECT_EQ(p.cable.weight_n_per_m, 1400.0);
  EXPECT_EQ(p.cable.axial_stiffness_n, 7.5e8);
  EXPECT_EQ(p.cable.mass_kg_per_m, 160.0);
  EXPECT_EQ(p.cable.added_mass_kg_per_m, 25.0);
}

TEST(LineSceneReader, NoModesAndNoForcingIsAStaticsOnlyScene) {
  const Scene scene = parse_one(kLine + "[request]\ninplane_modes = 0\noutofplane_modes = 0\n");
  EXPECT_EQ(scene.request.inplane_modes, 0);
  EXPECT_EQ(scene.request.outofplane_modes, 0);
  EXPECT_FALSE(scene.request.forced);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(LineSceneReader, BadLineInputNamesTheEntryAndField) {
  using testing::expect_invalid;
  auto parse = [](const std::string& text) {
    return [text] { parse_scene_text(text, "line.toml"); };
  };
  expect_invalid(parse(replaced(kLine, "length = 600.0", "length = 0.0")), "line.segments[1]");
  expect_invalid(parse(replaced(kLine, "s = 250.0", "s = 900.0")), "line.points[0].s");
  expect_invalid(parse(replaced(kLine, "s = 250.0", "s = -1.0")), "line.points[0]");
  expect_invalid(parse(replaced(kLine, "weight = 1.5e5", "weight = inf")), "line.points[0]");
  expect_invalid(parse(replaced(kLine, "mass = 8.0", "mass = -8.0")), "line.segments[1]");
  expect_invalid(parse(replaced(kLine, "EA = \"inf\"", "EA = \"rigid\"")), "line.segments[1]");
  expect_invalid(parse(kLine + "[[line.points]]\ns = 100.0\n"), "line.points[1].s");
  expect_invalid(parse("[line]\na = [0.0, 0.0]\nb = [1.0, 0.0]\n"), "line.segments");
  EXPECT_THROW(parse_scene_text(kLine + "colour = 1\n", "line.toml"), ParseError);
}

}  // namespace
}  // namespace catena
