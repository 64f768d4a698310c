// SPDX-License-Identifier: MIT
// report.json keeps the fields along the cable (mode shapes, forced response curves, the static
// profile) only when the scene asks for shapes; one record per line; tolerance reasons listed once;
// the checks as one table per scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "catena/io/json_writer.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/tolerance_reader.hpp"
#include "io/internal/check_table.hpp"

namespace catena {
namespace {

using nlohmann::json;

SceneResult solved(bool shapes) {
  SceneRunOptions options;
  options.tolerances = builtin_tolerance_table();
  options.only_solvers = {"fe", "shooting"};
  const Scene scene = parse_scene_text(
                          "[taut_inclined]\neps = 0.1\nphi_deg = 30.0\nlambda2 = "
                          "10.0\n[request]\ninplane_modes = 2\npoints = 21\n"
                          "shapes = " +
                              std::string(shapes ? "true" : "false") +
                              "\n[request.forced]\nfrequencies = [0.5]\namplitude = 0.001\n",
                          "layout.toml")
                          .front();
  return run_scene(scene, options);
}

TEST(JsonLayout, ShapesAndCurvesAreOmittedWhenNotAsked) {
  const json scene = json::parse(results_to_json({solved(false)}))["scenes"][0];
  const json& fe = scene["solvers"]["fe"];
  ASSERT_EQ(fe["inplane"]["modes"].size(), 2u);
  for (const auto& mode : fe["inplane"]["modes"]) EXPECT_FALSE(mode.contains("shape"));
  ASSERT_EQ(fe["forced"].size(), 1u);
  EXPECT_TRUE(fe["forced"][0]["max_abs_tension_n"].is_number());
  for (const char* curve : {"s_m", "u_m", "w_m", "v_m", "tension_n"})
    EXPECT_FALSE(fe["forced"][0].contains(curve));
  EXPECT_FALSE(scene["statics"].contains("shape"));
  EXPECT_TRUE(scene["statics"]["horizontal_force_n"].is_number());
}

TEST(JsonLayout, ShapesAndCurvesAreKeptWhenAsked) {
  const json scene = json::parse(results_to_json({solved(true)}))["scenes"][0];
  const json& fe = scene["solvers"]["fe"];
  EXPECT_EQ(fe["inplane"]["modes"][0]["shape"]["w"].size(), 21u);
  EXPECT_EQ(fe["forced"][0]["s_m"].size(), 21u);
  EXPECT_EQ(fe["forced"][0]["tension_n"].size(), 21u);
  EXPECT_EQ(scene["statics"]["shape"]["x_m"].size(), 21u);
}

TEST(JsonLayout, OneCheckPerLineAndEachToleranceReasonOnce) {
  const std::vector<SceneResult> results = {solved(false), solved(false)};
  const std::string text = results_to_json(results);
  const json document = json::parse(text);
  const json& reasons = document["tolerance_reasons"];
  ASSERT_FALSE(reasons.empty());
  for (std::size_t i = 0; i < reasons.size(); ++i) {
    for (std::size_t j = i + 1; j < reasons.size(); ++j) EXPECT_NE(reasons[i], reasons[j]);
  }
  int with_reason = 0;
  for (const auto& scene : document["scenes"]) {
    const json& fields = scene["checks"]["fields"];
    const auto reason_at =
        std::find(fields.begin(), fields.end(), "tolerance_reason") - fields.begin();
    ASSERT_LT(static_cast<std::size_t>(reason_at), fields.size());
    for (const auto& row : scene["checks"]["rows"]) {
      ASSERT_EQ(row.size(), fields.size());
      // The whole check is on one line of the text.
      EXPECT_NE(text.find(row.dump()), std::string::npos) << row.dump();
      if (row[reason_at].is_null()) continue;
      ++with_reason;
      EXPECT_LT(row[reason_at].get<std::size_t>(), reasons.size());
    }
  }
  EXPECT_GT(with_reason, 2 * static_cast<int>(reasons.size()) - 1);
}

// The check table reads back as the records the report works on; a PASS keeps no detail (its
// numbers are in the record), any other verdict keeps its reason.
TEST(JsonLayout, CheckTableExpandsToRecords) {
  const SceneResult result = solved(false);
  json document = json::parse(results_to_json({result}));
  internal::expand_check_tables(document);
  const json& records = document["scenes"][0]["checks"];
  ASSERT_EQ(records.size(), result.checks.size());
  for (std::size_t i = 0; i < records.size(); ++i) {
    const CheckResult& check = result.checks[i];
    EXPECT_EQ(records[i]["check"], check.check);
    EXPECT_EQ(records[i]["compare"], check.compare);
    EXPECT_EQ(records[i]["mode"], check.mode);
    EXPECT_EQ(records[i]["verdict"], to_string(check.verdict));
    EXPECT_EQ(records[i]["detail"], check.verdict == Verdict::Pass ? std::string() : check.detail);
  }
  json again = document;
  internal::expand_check_tables(again);  // records stay records
  EXPECT_EQ(again, document);
}

}  // namespace
}  // namespace catena
