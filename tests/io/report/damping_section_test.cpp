// SPDX-License-Identifier: MIT
// The damping tables of the report's scene section: present for a damped scene, with each mode's
// damping ratio and decay rate by solver and the overdamped roots apart; absent for an undamped
// scene (its section reads as before, report_test_support.hpp's scenes).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/report/report_test_support.hpp"
#include "io/report/sections.hpp"

namespace catena::internal {
namespace {

using Rows = std::vector<std::vector<std::string>>;
using Strings = std::vector<std::string>;

std::vector<Table> tables_of_class(const Document& document, const std::string& css) {
  std::vector<Table> found;
  for (const auto& block : document) {
    if (const auto* t = std::get_if<Table>(&block); t && t->css_class == css) found.push_back(*t);
  }
  return found;
}

json damped_scene() {
  return json::parse(R"({
    "name": "gale-damped", "description": "damped", "tags": ["gale", "damped"], "error": null,
    "problem": {"form": "gale", "cable": {"length_m": 1.0,
                "damping": {"tangential_n_s_per_m2": 0.1, "normal_n_s_per_m2": 0.1, "axial_n_s": 0.0}}},
    "statics": {"horizontal_force_n": 1.0},
    "solvers": {
      "frobenius": {"summary": {"termination": "converged"},
                    "inplane": {"modes": [
                      {"index": 1, "omega_rad_s": 2.4492754, "decay_rate_1_s": 2.0, "damping_ratio": 0.632},
                      {"index": 2, "omega_rad_s": 3.9393601, "decay_rate_1_s": 2.0, "damping_ratio": 0.453}],
                      "overdamped": [{"index": 1, "omega_rad_s": 0.0, "decay_rate_1_s": 1.2659811,
                                      "damping_ratio": 1.0}]}},
      "shooting": {"summary": {"termination": "converged"},
                   "inplane": {"modes": [
                     {"index": 1, "omega_rad_s": 2.4492754, "decay_rate_1_s": 2.0, "damping_ratio": 0.632}]}},
      "airy": {"summary": {"termination": "not-applicable", "message": "the line is damped"}}},
    "checks": []})");
}

TEST(ReportDamping, ADampedSceneGetsItsDampingRatiosBySolverAndItsOverdampedRoots) {
  const json scene = damped_scene();
  EXPECT_TRUE(is_damped_scene(scene));
  Document out;
  add_damping_tables(out, scene);
  const auto tables = tables_of_class(out, "damping");
  ASSERT_EQ(tables.size(), 2u);
  EXPECT_EQ(tables[0].header, (Strings{"in-plane damped mode", "frobenius zeta (delta [1/s])",
                                       "shooting zeta (delta [1/s])"}));
  EXPECT_EQ(tables[0].rows, (Rows{{"1", "0.632 (2)", "0.632 (2)"}, {"2", "0.453 (2)", "-"}}));
  EXPECT_EQ(tables[1].header,
            (Strings{"in-plane overdamped root", "frobenius zeta (delta [1/s])"}));
  EXPECT_EQ(tables[1].rows, (Rows{{"1", "1 (1.26598)"}}));
  ASSERT_TRUE(std::holds_alternative<Paragraph>(out[0]));
  EXPECT_NE(std::get<Paragraph>(out[0]).text.find("omega_d"), std::string::npos);
}

TEST(ReportDamping, ADampedSceneNoSolverComputedSaysSo) {
  json scene = damped_scene();
  scene["solvers"].erase("frobenius");
  scene["solvers"].erase("shooting");
  Document out;
  add_damping_tables(out, scene);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NE(std::get<Paragraph>(out[0]).text.find("no solver returned"), std::string::npos);
}

TEST(ReportDamping, UndampedScenesGetNoDampingSection) {
  const json document = testing::synthetic_results();
  for (const auto& scene : document["scenes"]) {
    EXPECT_FALSE(is_damped_scene(scene)) << scene["name"];
    Document out;
    add_damping_tables(out, scene);
    EXPECT_TRUE(out.empty());
  }
  Document all;
  add_scenes(all, document);
  EXPECT_TRUE(tables_of_class(all, "damping").empty());
  for (const auto& t : tables_of_class(all, "forced"))
    for (const auto& h : t.header) EXPECT_EQ(h.find("modulus"), std::string::npos) << h;
}

TEST(ReportDamping, TheScenesSectionOfADampedSceneCarriesTheTableAndTheModulus) {
  json document = testing::synthetic_results();
  json scene = damped_scene();
  scene["solvers"]["frobenius"]["forced"] =
      json::parse(R"([{"omega_rad_s": 1.3, "max_abs_tension_n": 0.5, "diagnostic": ""}])");
  document["scenes"].push_back(scene);
  Document all;
  add_scenes(all, document);
  EXPECT_EQ(tables_of_class(all, "damping").size(), 2u);
  const auto forced = tables_of_class(all, "forced");
  ASSERT_FALSE(forced.empty());
  EXPECT_EQ(forced.back().header.back(), "frobenius max|tau|/H (modulus)");
}

}  // namespace
}  // namespace catena::internal
