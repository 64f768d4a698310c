// SPDX-License-Identifier: MIT
// The results JSON: the documented layout (verification/README.md), null for non-finite values,
// and the scene error recorded.
#include "catena/io/json_writer.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "catena/io/scene_reader.hpp"
#include "catena/io/tolerance_reader.hpp"

namespace catena {
namespace {

using nlohmann::json;

SceneResult solved_inextensible() {
  SceneRunOptions options;
  options.tolerances = builtin_tolerance_table();
  options.only_solvers = {"fe"};
  const Scene scene = parse_scene_text(
                          "[cable]\nlength = 10.0\nweight = 1.0\nEA = \"inf\"\nmass = 1.0\na = "
                          "[0.0, 0.0]\nb = [8.0, 1.0]\n"
                          "[request]\ninplane_modes = 2\n",
                          "j.toml")
                          .front();
  return run_scene(scene, options);
}

TEST(JsonWriter, WritesTheDocumentedLayout) {
  const json document = json::parse(results_to_json({solved_inextensible()}));
  for (const char* key : {"version", "git", "compiler", "build_type", "generated_utc"}) {
    EXPECT_TRUE(document["catena"].contains(key)) << key;
  }
  ASSERT_EQ(document["scenes"].size(), 1u);
  const json& scene = document["scenes"][0];
  for (const char* key : {"name", "file", "description", "tags", "problem", "request", "statics",
                          "groups", "solvers", "published", "checks", "error", "wall_time_s"}) {
    EXPECT_TRUE(scene.contains(key)) << key;
  }
  EXPECT_TRUE(scene["error"].is_null());
  const json& modes = scene["solvers"]["fe"]["inplane"]["modes"];
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_EQ(modes[0]["index"], 1);
  EXPECT_GT(modes[0]["omega_rad_s"].get<double>(), 0.0);
  EXPECT_EQ(scene["solvers"]["fe"]["summary"]["termination"], "converged");
}

TEST(JsonWriter, NonFiniteValuesAreNull) {
  // EA = inf: lambda2 and the axial stiffness are infinite, written as null (never NaN/Infinity).
  const std::string text = results_to_json({solved_inextensible()});
  const json scene = json::parse(text)["scenes"][0];
  EXPECT_TRUE(scene["groups"]["lambda2"].is_null());
  EXPECT_TRUE(scene["problem"]["cable"]["axial_stiffness_n"].is_null());
  EXPECT_EQ(text.find("NaN"), std::string::npos);
  EXPECT_EQ(text.find("Infinity"), std::string::npos);
}

TEST(JsonWriter, SceneErrorIsWrittenWithoutStatics) {
  SceneResult failed;
  failed.scene.name = "broken";
  failed.error = "x.toml: no equilibrium";
  failed.error_kind = SceneError::BadInput;
  const json scene = json::parse(results_to_json({failed}, -1))["scenes"][0];
  EXPECT_EQ(scene["error"], "x.toml: no equilibrium");
  EXPECT_FALSE(scene.contains("statics"));
  EXPECT_TRUE(scene["solvers"].empty());
}

}  // namespace
}  // namespace catena
