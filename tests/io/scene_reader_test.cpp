// SPDX-License-Identifier: MIT
// Strict scene reading (docs/reference/scene-format.md; errors: docs/contributing/architecture.md,
// "Errors"). Compared: what the reader builds from scene text with what the text says; and, for
// every kind of bad input, that the error is the right exception and names the table, the key and
// the reason.
#include "catena/io/scene_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "catena/core/error.hpp"
#include "test_utils.hpp"

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

TEST(SceneReader, ReadsThePhysicalFormAndRequest) {
  const auto scenes = parse_scene_text("name = \"m\"\n" + kCable + R"(
[request]
inplane_modes = 4
outofplane_modes = 3
shapes = true
points = 51
tension = true
[request.forced]
end = "a"
direction = "normal"
amplitude = 0.5
frequencies = [0.1, 0.2]
frequency_unit = "Hz"
[solvers]
shooting = {}
[checks]
frequency_rel = 1e-6
mac_min = 0.99
[[published]]
source = "made up"
quantity = "inplane_frequency"
unit = "rad/s"
modes = [1, 2]
values = [0.1, 0.2]
decimals = 2
)",
                                       "test.toml");
  ASSERT_EQ(scenes.size(), 1u);
  const Scene& s = scenes[0];
  EXPECT_EQ(s.name, "m");
  EXPECT_EQ(s.problem.cable.length_m, 1000.0);
  EXPECT_EQ(s.problem.cable.added_mass_kg_per_m, 80.0);
  EXPECT_EQ(s.problem.supports.b_m, Vec2(900.0, 300.0));
  EXPECT_EQ(s.request.inplane_modes, 4);
  EXPECT_EQ(s.request.outofplane_modes, 3);
  EXPECT_TRUE(s.request.shapes);
  EXPECT_EQ(s.request.points, 51);
  ASSERT_TRUE(s.request.forced.has_value());
  EXPECT_EQ(s.request.forced->end, CableEnd::A);
  EXPECT_EQ(s.request.forced->direction, ForcingDirection::Normal);
  EXPECT_EQ(s.forcing_frequency_unit, FrequencyUnit::Hertz);
  EXPECT_EQ(s.solver_names(), std::vector<std::string>{"shooting"});
  EXPECT_EQ(*s.checks.mac_min, 0.99);
  ASSERT_EQ(s.published.size(), 1u);
  EXPECT_EQ(s.published[0].decimals, 2);
}

TEST(SceneReader, AcceptsInfiniteStiffnessAsNumberOrString) {
  for (const char* ea : {"inf", "\"inf\""}) {
    const std::string text = std::string("[cable]\nlength = 10.0\nweight = 1.0\nEA = ") + ea +
                             "\nmass = 1.0\na = [0.0, 0.0]\nb = [5.0, 0.0]\n";
    EXPECT_TRUE(parse_scene_text(text, "x.toml")[0].problem.cable.is_inextensible());
  }
}

TEST(SceneReader, ExpandsASweepIntoOneScenePerValue) {
  const auto scenes = parse_scene_text(R"(
name = "irvine"
[taut_inclined]
eps = 0.01
phi_deg = 0.0
lambda2 = 1.0
[sweep]
parameter = "taut_inclined.lambda2"
values = [1.0, 10.0, 100.0]
)",
                                       "sweep.toml");
  ASSERT_EQ(scenes.size(), 3u);
  EXPECT_EQ(scenes[1].name, "irvine[lambda2=10]");
  EXPECT_EQ(scenes[2].sweep_point->second, 100.0);
}

TEST(SceneReader, GaleFormsBuildInextensibleCatenaries) {
  const auto a = parse_scene_text("[gale]\nxi1 = -0.34\nxi2 = 0.34\n", "g.toml");
  const auto b = parse_scene_text("[gale]\nh_over_b = 0.0\nsag_param = 0.9\n", "g.toml");
  EXPECT_TRUE(a[0].problem.cable.is_inextensible());
  EXPECT_EQ(b[0].problem.form, ProblemForm::GaleSag);
}

// --- bad input: each case is the scene text, the exception it must raise, and words the message
// must contain (the table/key and the reason). ---
struct BadScene {
  const char* label;
  std::string text;
  bool parse_error;  // ParseError (file/format) vs InvalidInput (value)
  std::vector<std::string> words;
};

std::string cable_with(const std::string& key, const std::string& value) {
  std::string text = kCable;
  const auto at = text.find(key + " = ");
  const auto end = text.find('\n', at);
  return text.replace(at, end - at, key + " = " + value);
}

std::vector<BadScene> bad_scenes() {
  return {
      {"negative length", cable_with("length", "-1.0"), false, {"[cable].length", "> 0"}},
      {"zero weight", cable_with("weight", "0.0"), false, {"[cable].weight", "> 0"}},
      {"zero mass", cable_with("mass", "0"), false, {"[cable].mass", "> 0"}},
      {"negative added mass",
       cable_with("added_mass", "-3.0"),
       false,
       {"[cable].added_mass", ">= 0"}},
      {"negative EA", cable_with("EA", "-5.0"), false, {"[cable].EA", "> 0"}},
      {"EA as bad string", cable_with("EA", "\"stiff\""), false, {"[cable].EA", "inf"}},
      {"NaN length", cable_with("length", "nan"), false, {"[cable].length"}},
      {"inf mass", cable_with("mass", "inf"), false, {"[cable].mass"}},
      {"wrong type",
       cable_with("length", "\"long\""),
       true,
       {"[cable].length", "expected a number"}},
      {"point with 3 numbers",
       cable_with("b", "[1.0, 2.0, 3.0]"),
       false,
       {"[cable].b", "2 numbers"}},
      {"point not an array", cable_with("a", "0.0"), true, {"[cable].a", "array"}},
      {"unknown key in cable",
       kCable + "colour = \"red\"\n",
       true,
       {"[cable].colour", "unknown key"}},
      {"unknown top-level key", "foo = 1\n" + kCable, true, {"foo", "unknown key"}},
      {"missing key", "[cable]\nlength = 1.0\n", true, {"[cable].weight", "missing"}},
      {"no cable table", "name = \"x\"\n", true, {"exactly one of"}},
      {"cable and line",
       kCable + "[line]\na = [0.0, 0.0]\nb = [1.0, 0.0]\n",
       true,
       {"exactly one of", "found 2"}},
      {"two cable forms",
       kCable + "[gale]\nxi1 = -0.1\nxi2 = 0.1\n",
       true,
       {"exactly one of", "found 2"}},
      {"coincident supports", cable_with("b", "[0.0, 0.0]"), false, {"[cable]", "coincide"}},
      {"b left of a", cable_with("b", "[-900.0, 300.0]"), false, {"[cable]", "left of"}},
      {"TOML syntax", "[cable\nlength = 1", true, {"TOML syntax"}},
      {"negative mode count",
       kCable + "[request]\ninplane_modes = -2\n",
       false,
       {"[request].inplane_modes", "[0, 1000]"}},
      {"modes as float",
       kCable + "[request]\ninplane_modes = 2.5\n",
       true,
       {"[request].inplane_modes", "integer"}},
      {"one point", kCable + "[request]\npoints = 1\n", false, {"[request].points"}},
      // A request for no modes and no forcing is a statics-only scene (line_scene_reader_test.cpp).
      {"unknown request key",
       kCable + "[request]\nmodes = 3\n",
       true,
       {"[request].modes", "unknown key"}},
      {"bad forcing direction",
       kCable + "[request.forced]\ndirection = \"up\"\nfrequencies = [1.0]\n",
       false,
       {"[request.forced].direction", "tangential"}},
      {"negative forcing frequency",
       kCable + "[request.forced]\nfrequencies = [-1.0]\n",
       false,
       {"[request.forced].frequencies", ">= 0"}},
      {"zero amplitude",
       kCable + "[request.forced]\namplitude = 0.0\nfrequencies = [1.0]\n",
       false,
       {"[request.forced].amplitude", "> 0"}},
      {"bad frequency unit",
       kCable + "[request.forced]\nfrequencies = [1.0]\nfrequency_unit = \"rpm\"\n",
       false,
       {"frequency_unit", "rad/s"}},
      {"unknown solver",
       kCable + "[solvers]\nmagic = {}\n",
       true,
       {"[solvers].magic", "unknown solver"}},
      {"taut phi 90",
       "[taut_inclined]\neps = 0.1\nphi_deg = 90.0\nlambda2 = 1.0\n",
       false,
       {"[taut_inclined]", "phi_deg"}},
      {"taut mass ratio > 1",
       "[taut_inclined]\neps = 0.1\nphi_deg = 10.0\nlambda2 = 1.0\nmass_ratio = 2.0\n",
       false,
       {"[taut_inclined]", "mass_ratio"}},
      {"gale xi1 >= xi2", "[gale]\nxi1 = 0.3\nxi2 = 0.3\n", false, {"[gale]", "xi1 < xi2"}},
      {"gale both forms",
       "[gale]\nxi1 = -0.3\nxi2 = 0.3\nsag_param = 0.9\n",
       true,
       {"[gale]", "not both"}},
      {"gale sag >= 1",
       "[gale]\nh_over_b = 0.0\nsag_param = 1.2\n",
       false,
       {"[gale]", "sag_param"}},
      {"mac_min > 1", kCable + "[checks]\nmac_min = 1.5\n", false, {"[checks].mac_min", "(0, 1]"}},
      {"published without source",
       kCable + "[[published]]\nquantity = \"inplane_frequency\"\nmodes = [1]\nvalues = [1.0]\n",
       true,
       {"source", "missing"}},
      {"published count mismatch",
       kCable + "[[published]]\nsource = \"x\"\nquantity = \"inplane_frequency\"\nmodes = [1, "
                "2]\nvalues = [1.0]\n",
       false,
       {"values", "1 values for 2 modes"}},
      // Integers are range-checked before any cast: 2^31 and 1e20 used to wrap to -2^31.
      {"published mode beyond int",
       kCable + "[[published]]\nsource = \"x\"\nquantity = \"inplane_frequency\"\nmodes = "
                "[2147483648]\nvalues = [1.0]\n",
       false,
       {"modes", "2147483648", "integer in [0, 1000]"}},
      {"published mode 1e20",
       kCable + "[[published]]\nsource = \"x\"\nquantity = \"inplane_frequency\"\nmodes = "
                "[1e20]\nvalues = [1.0]\n",
       false,
       {"modes", "integer in [0, 1000]"}},
      {"decimals beyond int",
       kCable + "[[published]]\nsource = \"x\"\nquantity = \"inplane_frequency\"\nmodes = "
                "[1]\nvalues = [1.0]\n"
                "decimals = -2147483649\n",
       false,
       {"decimals = -2147483649", "[0, 17]"}},
      {"too many points",
       kCable + "[request]\npoints = 100001\n",
       false,
       {"[request].points", "[2, 100000]"}},
      {"too many shape values",
       kCable + "[request]\npoints = 100000\ninplane_modes = 20\nshapes = true\n",
       false,
       {"[request]", "shape values", "1000000"}},
      // Magnitudes whose products overflow the statics are refused naming the field, not reported
      // as "closure error -nan" or as coincident supports.
      {"huge length",
       cable_with("length", "1e300"),
       false,
       {"[cable]", "length_m = 1e+300", "1e+15"}},
      {"huge weight", cable_with("weight", "1e300"), false, {"[cable]", "weight_n_per_m", "1e+15"}},
      {"huge EA", cable_with("EA", "1e300"), false, {"[cable]", "axial_stiffness_n", "1e+30"}},
      {"huge support coordinate",
       cable_with("b", "[1e308, 0.0]"),
       false,
       {"[cable]", "b = (1e+308, 0)", "within"}},
      {"sweep of unknown table",
       kCable + "[sweep]\nparameter = \"gale.xi1\"\nvalues = [1.0]\n",
       false,
       {"[sweep]", "no table [gale]"}},
  };
}

TEST(SceneReader, RejectsEveryKindOfBadInputWithANamedReason) {
  const auto cases = bad_scenes();
  EXPECT_GE(cases.size(), 20u);
  for (const auto& bad : cases) {
    try {
      parse_scene_text(bad.text, "bad.toml");
      ADD_FAILURE() << bad.label << ": no error";
    } catch (const ParseError& error) {
      EXPECT_TRUE(bad.parse_error)
          << bad.label << ": ParseError, expected InvalidInput: " << error.what();
      for (const auto& word : bad.words) {
        EXPECT_NE(std::string(error.what()).find(word), std::string::npos)
            << bad.label << ": message lacks '" << word << "': " << error.what();
      }
      EXPECT_NE(std::string(error.what()).find("bad.toml"), std::string::npos)
          << bad.label << ": " << error.what();
    } catch (const InvalidInput& error) {
      EXPECT_FALSE(bad.parse_error)
          << bad.label << ": InvalidInput, expected ParseError: " << error.what();
      for (const auto& word : bad.words) {
        EXPECT_NE(std::string(error.what()).find(word), std::string::npos)
            << bad.label << ": message lacks '" << word << "': " << error.what();
      }
      EXPECT_NE(std::string(error.what()).find("bad.toml"), std::string::npos)
          << bad.label << ": " << error.what();
    }
  }
}

// toml11 parses nested arrays and inline tables recursively: about 5,900 / 3,500 levels overflowed
// the stack (SIGSEGV). The depth is now checked on the text before the parser sees it.
TEST(SceneReader, DeepNestingIsAParseErrorNotAStackOverflow) {
  for (const auto& [open, close, levels] :
       {std::tuple{"[", "]", 5900}, std::tuple{"{x=", "}", 3500}}) {
    std::string deep = kCable + "deep = ";
    for (int i = 0; i < levels; ++i) deep += open;
    deep += "1";
    for (int i = 0; i < levels; ++i) deep += close;
    try {
      parse_scene_text(deep + "\n", "deep.toml");
      ADD_FAILURE() << open << ": no error";
    } catch (const ParseError& error) {
      EXPECT_NE(std::string(error.what())
                    .find("deep.toml: line 10: arrays and inline tables nested deeper than 64"),
                std::string::npos)
          << error.what();
    }
  }
  // At the limit the parser runs (and rejects the unknown key, naming it).
  std::string at_limit =
      kCable + "deep = " + std::string(63, '[') + "1" + std::string(63, ']') + "\n";
  EXPECT_THROW(
      try { parse_scene_text(at_limit, "x.toml"); } catch (const ParseError& error) {
        EXPECT_NE(std::string(error.what()).find("[cable].deep"), std::string::npos)
            << error.what();
        throw;
      },
      ParseError);
  // Brackets in strings and comments are not nesting.
  const std::string brackets(500, '[');
  EXPECT_NO_THROW(parse_scene_text("description = \"" + brackets + "\"\n# " + brackets + "\n" +
                                       "name = \'\'\'" + std::string(500, '{') + "\'\'\'\n" +
                                       kCable,
                                   "strings.toml"));
}

TEST(SceneReader, MissingFileIsAParseErrorNamingThePath) {
  try {
    read_scene_file("/nonexistent/scene.toml");
    FAIL();
  } catch (const ParseError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/scene.toml"), std::string::npos);
  }
}

}  // namespace
}  // namespace catena
