// SPDX-License-Identifier: MIT
// The readers' tables: source discrepancies grouped by published entry (one row however many
// solvers judged it), the headline counts by check kind and by solver pair, the mutation score with
// every uncaught mutation listed, and the analytic models' fitted order of error in eps.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/report/report_test_support.hpp"
#include "io/report/sections.hpp"

namespace catena::internal {
namespace {

using Rows = std::vector<std::vector<std::string>>;

std::vector<Table> tables(const Document& document) {
  std::vector<Table> found;
  for (const auto& block : document) {
    if (const auto* t = std::get_if<Table>(&block)) found.push_back(*t);
  }
  return found;
}

json published_check(const std::string& solver,
                     int mode,
                     const std::string& verdict,
                     const std::string& detail) {
  return {{"check", "published"}, {"compare", solver + " vs Gale 1976"},
          {"plane", "in-plane"},  {"mode", mode},
          {"value_a", 1.0},       {"value_b", 1.2},
          {"measured", 0.2},      {"tolerance", 0.005},
          {"verdict", verdict},   {"detail", detail}};
}

TEST(DiscrepancyTable, OneRowPerPublishedEntryWhateverTheNumberOfSolvers) {
  json document = testing::synthetic_results();
  json& checks = document["scenes"][0]["checks"];
  checks = json::array(
      {published_check("fe", 1, "SOURCE", "ours 1.1; confirmed by frobenius = 1.1"),
       published_check("frobenius", 1, "SOURCE", "ours 1.1; confirmed by fe = 1.1"),
       published_check("fe", 3, "PASS", ""), published_check("frobenius", 3, "PASS", "")});
  Document out;
  EXPECT_EQ(add_discrepancies(out, document), 1);  // two SOURCE checks, one entry
  ASSERT_EQ(tables(out).size(), 1u);
  EXPECT_EQ(tables(out)[0].rows,
            (Rows{{"gale-a", "Gale 1976", "1", "1.1", "1.1", "-", "1.1000001",
                   "fe SOURCE, frobenius SOURCE", "confirmed by frobenius = 1.1"}}));
}

TEST(HeadlineTables, CountEachVerdictByKindAndBySolverPair) {
  Document out;
  add_headline(out, testing::synthetic_results());
  const auto t = tables(out);
  ASSERT_EQ(t.size(), 2u);
  const std::vector<std::string> header = {"check", "checks", "PASS", "FAIL",
                                           "WARN",  "SOURCE", "SKIP"};
  EXPECT_EQ(t[0].header, header);
  EXPECT_EQ(t[0].rows, (Rows{{"agreement", "2", "0", "2", "0", "0", "0"},
                             {"error_estimate", "1", "0", "0", "1", "0", "0"},
                             {"published", "2", "1", "0", "0", "1", "0"}}));
  // Published comparisons are grouped by solver against "published", whatever the source.
  EXPECT_EQ(t[1].rows, (Rows{{"fe", "1", "0", "0", "1", "0", "0"},
                             {"fe vs frobenius", "1", "0", "1", "0", "0", "0"},
                             {"fe vs published", "1", "0", "0", "0", "1", "0"},
                             {"frobenius vs published", "1", "1", "0", "0", "0", "0"},
                             {"shooting vs fe", "1", "0", "1", "0", "0", "0"}}));
}

json mutation_block() {
  return json::parse(
      R"({"wall_time_s": 1.5, "threads": 2, "frequency_factor": 10.0, "shape_factor": 10.0,
    "forced_tension_relative": 1e-4,
    "default_accuracy_targets": {"fe": 1e-7, "shooting": 1.1e-9},
    "exact_with_witness": {"made": 4, "caught": 2}, "exact_beyond_estimate": {"made": 2, "caught": 2},
    "tallies": [{"solver": "fe", "family": "gale", "quantity": "frequency", "made": 3, "caught": 1},
                {"solver": "fe", "family": "gale", "quantity": "forced-tension", "made": 1, "caught": 1}],
    "uncaught": [{"scene": "gale-a", "family": "gale", "solver": "fe", "quantity": "frequency",
                  "plane": "in-plane", "exact_witness": true, "modes": [2, 3], "sizes": [1e-6, 1e-6],
                  "estimates": [2e-6, -1.0]}]})");
}

TEST(MutationSection, ScoresBySolverAndFamilyAndListsEveryUncaughtMutation) {
  json document = testing::synthetic_results();
  document["mutation"] = mutation_block();
  Document out;
  add_mutation(out, document);
  const auto t = tables(out);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].rows, (Rows{{"fe", "gale", "4", "2", "2", "50.0%"}}));
  EXPECT_EQ(t[1].rows, (Rows{{"fe", "forced-tension", "1", "1", "0", "100.0%"},
                             {"fe", "frequency", "3", "1", "2", "33.3%"}}));
  EXPECT_EQ(
      t[2].rows,
      (Rows{{"gale-a", "fe", "frequency", "in-plane", "2, 3", "1e-06, 1e-06", "2e-06, -", "yes"}}));
  // The prose states the run's targets and the registry's exact solvers and models.
  std::string prose;
  for (const Block& block : out)
    if (const auto* p = std::get_if<Paragraph>(&block)) prose += p->text;
  EXPECT_NE(prose.find("default knobs: fe 1e-07, shooting 1.1e-09"), std::string::npos) << prose;
  EXPECT_NE(prose.find("asymptotic and airy their model-error estimate"), std::string::npos);
  EXPECT_NE(prose.find("Exact solvers (fe, shooting, frobenius)"), std::string::npos);
}

TEST(MutationSection, AbsentWithoutAMutationRun) {
  Document out;
  add_mutation(out, testing::synthetic_results());
  EXPECT_TRUE(out.empty());
}

// A scene where asymptotic's error is exactly 0.5 eps^2 against shooting.
json model_scene(double eps) {
  const double omega = 2.0, error = 0.5 * eps * eps;
  json mode_exact = {{"index", 1}, {"omega_rad_s", omega}, {"relative_error_estimate", 1e-12}};
  json mode_model = {
      {"index", 1}, {"omega_rad_s", omega * (1.0 + error)}, {"relative_error_estimate", eps * eps}};
  json converged = {{"termination", "converged"}};
  return {{"name", "s" + std::to_string(eps)},
          {"groups", {{"eps", eps}, {"lambda2", 10.0}, {"chord_angle_deg", 30.0}}},
          {"solvers",
           {{"shooting", {{"summary", converged}, {"inplane", {{"modes", {mode_exact}}}}}},
            {"asymptotic", {{"summary", converged}, {"inplane", {{"modes", {mode_model}}}}}}}},
          {"checks", json::array()}};
}

TEST(ModelError, FitsTheOrderOfAnExactPowerLawAndWritesEveryPoint) {
  json document = {{"scenes", json::array()}};
  for (double eps : {0.01, 0.03, 0.1, 0.2, 0.5}) document["scenes"].push_back(model_scene(eps));
  const auto dir = std::filesystem::temp_directory_path() / "catena_model_error_test";
  Document out;
  add_model_error(out, document, dir);
  const auto t = tables(out);
  ASSERT_EQ(t.size(), 2u);
  // eps = 0.5 is outside the asymptotic range (eps <= 0.3): four scenes fitted, p = 2, C = 0.5.
  EXPECT_EQ(t[0].rows,
            (Rows{{"asymptotic", "inplane", "all", "all", "4", "0.01 - 0.2", "2.00", "0.5"},
                  {"asymptotic", "inplane", "10", "30", "4", "0.01 - 0.2", "2.00", "0.5"}}));
  EXPECT_EQ(t[1].rows.size(), 5u);
  EXPECT_TRUE(std::filesystem::exists(dir / "model-error.csv"));
  std::filesystem::remove_all(dir);
}

// Found by the report fuzz target: a subnormal eps (1e-308 in a results file) made the by-eps
// table's rounding (std::stod of "1e-308") throw out_of_range: an internal error.
TEST(ModelError, ASubnormalEpsIsARowNotAnException) {
  json document = {{"scenes", json::array()}};
  for (double eps : {1e-308, 0.01, 0.1}) document["scenes"].push_back(model_scene(eps));
  const auto dir = std::filesystem::temp_directory_path() / "catena_model_error_subnormal";
  Document out;
  EXPECT_NO_THROW(add_model_error(out, document, dir));
  const auto t = tables(out);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[1].rows.size(), 3u);  // one row per eps, the subnormal one included
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace catena::internal
