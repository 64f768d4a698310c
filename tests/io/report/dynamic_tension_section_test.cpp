// SPDX-License-Identifier: MIT
// The dynamic-tension table of the report's scene section: one row per excitation and solver with
// the fairlead and anchor values (amplitude; standard deviation and most probable maximum when
// irregular), the fixed point's iterations and residual and the dynamic-tension check's agreement
// at the fairlead, read from a hand-written results scene in the JSON names of issue 30; absent
// for a scene without a motion request (report_test_support.hpp's scenes).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/report/report_test_support.hpp"
#include "io/report/sections.hpp"

namespace catena::internal {
namespace {

using Rows = std::vector<std::vector<std::string>>;

const Table* dynamic_table(const Document& document) {
  for (const auto& block : document) {
    if (const auto* t = std::get_if<Table>(&block); t && t->css_class == "dynamic-tension")
      return t;
  }
  return nullptr;
}

json motion_scene() {
  return json::parse(R"({
    "name": "chain-drag", "tags": ["drag"], "error": null,
    "statics": {"horizontal_force_n": 1.0e5},
    "solvers": {
      "fe": {"summary": {"termination": "converged"}, "dynamic_tension": [
        {"period_s": 8.0, "iterations": 15, "residual": 3.2e-9, "converged": true,
         "fairlead": {"s_m": 1000.0, "mean_n": 3.1e5, "amplitude_n": 201234.4},
         "anchor": {"s_m": 0.0, "mean_n": 1.2e5, "amplitude_n": 50123.4}},
        {"period_s": 12.0, "iterations": 200, "residual": 4e-3, "converged": false,
         "fairlead": {"s_m": 1000.0, "mean_n": 3.1e5, "amplitude_n": 1.5e5},
         "anchor": {"s_m": 0.0, "mean_n": 1.2e5, "amplitude_n": 4.0e4}}]},
      "shooting": {"summary": {"termination": "converged"}, "dynamic_tension": [
        {"period_s": 8.0, "iterations": 14, "residual": 1.1e-9, "converged": true,
         "fairlead": {"s_m": 1000.0, "mean_n": 3.1e5, "amplitude_n": 201234.6},
         "anchor": {"s_m": 0.0, "mean_n": 1.2e5, "amplitude_n": 50123.4}}]},
      "frobenius": {"summary": {"termination": "not-applicable"}}},
    "checks": [
      {"check": "dynamic-tension", "compare": "fe vs shooting", "plane": "fairlead", "mode": 1,
       "measured": 5.0e-7, "verdict": "PASS"},
      {"check": "dynamic-tension", "compare": "fe vs shooting", "plane": "anchor", "mode": 1,
       "measured": 0.0, "verdict": "PASS"}]})");
}

TEST(ReportDynamicTension, AMotionSceneGetsItsEndValuesFixedPointsAndAgreement) {
  Document out;
  add_dynamic_tension_table(out, motion_scene());
  const Table* t = dynamic_table(out);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->header.size(), 6u);
  EXPECT_EQ(
      t->rows,
      (Rows{{"T = 8 s", "fe", "201234", "50123.4", "15 / 3.2e-09", "vs shooting 5.0e-07 PASS"},
            {"T = 8 s", "shooting", "201235", "50123.4", "14 / 1.1e-09", "vs fe 5.0e-07 PASS"},
            {"T = 12 s", "fe", "150000", "40000", "200 / 4.0e-03 NOT converged", "-"}}));
}

TEST(ReportDynamicTension, IrregularMotionShowsSigmaAndTheMostProbableMaximum) {
  json scene = motion_scene();
  scene["solvers"].erase("shooting");
  json& e = scene["solvers"]["fe"]["dynamic_tension"];
  e = json::array({e[0]});
  e[0].erase("period_s");
  e[0]["fairlead"] = {
      {"s_m", 1000.0}, {"mean_n", 3.1e5}, {"std_n", 4.2e4}, {"most_probable_max_n", 4.7e5}};
  e[0]["anchor"] = {
      {"s_m", 0.0}, {"mean_n", 1.2e5}, {"std_n", 1.0e4}, {"most_probable_max_n", 1.6e5}};
  Document out;
  add_dynamic_tension_table(out, scene);
  const Table* t = dynamic_table(out);
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->rows.size(), 1u);
  EXPECT_EQ(t->rows[0][0], "irregular");
  EXPECT_EQ(t->rows[0][2], "42000 (max 470000)");
  EXPECT_EQ(t->rows[0][3], "10000 (max 160000)");
}

TEST(ReportDynamicTension, ScenesWithoutAMotionGetNoTable) {
  const json document = testing::synthetic_results();
  for (const auto& scene : document["scenes"]) {
    Document out;
    add_dynamic_tension_table(out, scene);
    EXPECT_TRUE(out.empty()) << scene["name"];
  }
}

}  // namespace
}  // namespace catena::internal
