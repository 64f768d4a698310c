// SPDX-License-Identifier: MIT
// The report's sections built from a hand-written results document (report_test_support.hpp):
// every table checked cell by cell, including the counts, the units, the published columns, the
// forced maxima over H and the stress outcomes.
#include "io/report/sections.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/report/report_test_support.hpp"

namespace catena::internal {
namespace {

using Rows = std::vector<std::vector<std::string>>;
using Strings = std::vector<std::string>;

// The blocks of one kind, in document order.
template <class Block>
std::vector<Block> blocks_of(const Document& document) {
  std::vector<Block> found;
  for (const auto& block : document) {
    if (const auto* b = std::get_if<Block>(&block)) found.push_back(*b);
  }
  return found;
}

std::vector<Table> tables(const Document& document) { return blocks_of<Table>(document); }

const json document = testing::synthetic_results();

TEST(ReportSections, SummaryCountsEachVerdictAndNamesTheBuild) {
  Document out;
  add_summary(out, document);
  ASSERT_EQ(out.size(), 3u);
  const auto& title = std::get<Heading>(out[0]);
  EXPECT_EQ(title.level, 1);
  EXPECT_EQ(title.text, "Catena verification report");
  EXPECT_EQ(title.anchor, "top");
  EXPECT_EQ(std::get<Paragraph>(out[1]).text,
            "catena 1.2.3 (git abc1234) · gcc 12 · Release · 2024-05-01T12:00:00Z · 2 scenes, 5 "
            "checks, 2 failed, "
            "1 source discrepancies");
  const Table& t = std::get<Table>(out[2]);
  EXPECT_EQ(t.header, (Strings{"verdict", "checks", "meaning"}));
  ASSERT_EQ(t.rows.size(), 5u);
  const Strings verdicts = {t.rows[0][0], t.rows[1][0], t.rows[2][0], t.rows[3][0], t.rows[4][0]};
  const Strings counts = {t.rows[0][1], t.rows[1][1], t.rows[2][1], t.rows[3][1], t.rows[4][1]};
  EXPECT_EQ(verdicts, (Strings{"FAIL", "PASS", "SKIP", "SOURCE", "WARN"}));
  EXPECT_EQ(counts, (Strings{"2", "1", "0", "1", "1"}));
  EXPECT_EQ(t.rows[0][2], "beyond tolerance: a defect of ours");
}

TEST(ReportSections, SolversTableCountsRunsAndTakesMedianTimesAndLargestEstimates) {
  Document out;
  add_solvers(out, document);
  ASSERT_EQ(tables(out).size(), 1u);
  const Table t = tables(out)[0];
  EXPECT_EQ(t.css_class, "solvers");
  // Solvers in name order; a declined run counts as declined only (no time, no estimate). fe's
  // median of (2 ms, 10 ms) is the upper one; shooting has no estimate (null): 0.
  EXPECT_EQ(t.rows, (Rows{{"airy", "0", "0", "0", "1", "0", "0", "0.00e+00"},
                          {"fe", "2", "1", "1", "0", "10", "0.012", "1.00e-09"},
                          {"frobenius", "1", "1", "0", "0", "4", "0.004", "1.00e-12"},
                          {"shooting", "1", "1", "0", "0", "1", "0.001", "0.00e+00"}}));
}

TEST(ReportSections, DiscrepanciesListOnlySourceVerdicts) {
  Document out;
  add_discrepancies(out, document);
  ASSERT_EQ(tables(out).size(), 1u);
  // One row per published entry: the printed value, each exact solver's value in the table's unit
  // (shooting did not run), every solver's verdict on the entry, and the diagnosis.
  EXPECT_EQ(tables(out)[0].rows, (Rows{{"gale-a", "Gale 1976", "1", "1.1", "1.1", "-", "1.1000001",
                                        "fe SOURCE, frobenius PASS", "misprint"}}));
  EXPECT_EQ(std::get<Heading>(out[0]).anchor, "source-discrepancies");
}

TEST(ReportSections, NoDiscrepancySaysNone) {
  json clean = document;
  clean["scenes"][0]["checks"][0]["verdict"] = "PASS";
  Document out;
  add_discrepancies(out, clean);
  EXPECT_TRUE(tables(out).empty());
  EXPECT_EQ(std::get<Paragraph>(out.back()).text, "None.");
}

TEST(ReportSections, FailuresListSceneErrorsFailsAndWarnsInSceneOrder) {
  Document out;
  add_failures(out, document);
  ASSERT_EQ(tables(out).size(), 1u);
  EXPECT_EQ(
      tables(out)[0].rows,
      (Rows{{"gale-a", "agreement", "fe vs frobenius", "inplane", "2", "4.340e-02", "1.000e-06",
             "FAIL", "too far"},
            {"gale-a", "error_estimate", "fe", "inplane", "1", "2.000e-05", "1.000e-05", "WARN",
             "estimate large"},
            {"stress-1", "scene", "-", "-", "-", "-", "-", "FAIL", "statics did not converge"},
            {"stress-1", "agreement", "shooting vs fe", "inplane", "1", "4.000e-01", "1.000e-08",
             "FAIL", "disagree"}}));
}

TEST(ReportSections, StressOutcomesJudgeEachSolverByItsOwnChecks) {
  Document out;
  add_stress_outcomes(out, document);
  ASSERT_EQ(tables(out).size(), 1u);
  EXPECT_EQ(std::get<Heading>(out[0]).text, "Stress suite outcomes");
  // The FAIL check names both solvers, so both carry it; fe failed numerically (diagnosed, its
  // message cut to 160 characters), shooting converged to a failing value (FAIL).
  const Table t = tables(out)[0];
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0], (Strings{"stress-1", "fe", "diagnosed", "1",
                                testing::long_failure_message().substr(0, 157) + "..."}));
  EXPECT_EQ(t.rows[0][4].size(), 160u);
  EXPECT_EQ(t.rows[1], (Strings{"stress-1", "shooting", "FAIL", "1", "ok"}));
}

TEST(ReportSections, StressOutcomesOfPassingAndDecliningSolvers) {
  json run = document;
  run["scenes"][1]["checks"][0]["compare"] = "fe vs published";  // no longer about shooting
  run["scenes"][1]["solvers"]["fe"]["summary"]["termination"] = "not-applicable";
  Document out;
  add_stress_outcomes(out, run);
  const Table t = tables(out).at(0);
  EXPECT_EQ(t.rows[0][2], "declined");
  EXPECT_EQ(t.rows[1][2], "accurate");
  EXPECT_EQ(t.rows[1][3], "0");
}

TEST(ReportSections, NoStressSceneAddsNothing) {
  json run = document;
  run["scenes"].erase(1);
  Document out;
  add_stress_outcomes(out, run);
  EXPECT_TRUE(out.empty());
}

TEST(ReportSections, TimeToAccuracyShowsMillisecondsOrCannot) {
  Document out;
  add_time_to_accuracy(out, {});
  EXPECT_TRUE(out.empty());  // no baseline, no section
  TimeToAccuracy timing;
  timing.cases = {"taut", "listed-but-never-timed"};
  timing.best_time_s["taut"]["fe"] = {{1e-3, 0.0005}, {1e-6, 0.012}};
  timing.best_time_s["taut"]["airy"] = {{1e-3, 2e-5}};
  add_time_to_accuracy(out, timing);
  ASSERT_EQ(tables(out).size(), 1u);
  EXPECT_EQ(tables(out)[0].header, (Strings{"case", "solver", "1e-3", "1e-6", "1e-9"}));
  EXPECT_EQ(tables(out)[0].rows, (Rows{{"taut", "airy", "0.02 ms", "cannot", "cannot"},
                                       {"taut", "fe", "0.5 ms", "12 ms", "cannot"}}));
}

TEST(ReportSections, ScenesHaveAHeadingAnInfoLineAndTheirTables) {
  Document out;
  add_scenes(out, document);
  const auto headings = blocks_of<Heading>(out);
  ASSERT_EQ(headings.size(), 3u);
  EXPECT_EQ(headings[1].text, "gale-a");
  EXPECT_EQ(headings[1].anchor, "gale-a");
  EXPECT_EQ(headings[1].level, 3);
  EXPECT_EQ(headings[2].text, "stress-1");
  const auto paragraphs = blocks_of<Paragraph>(out);
  ASSERT_EQ(paragraphs.size(), 2u);
  EXPECT_EQ(paragraphs[0].text,
            "Gale's sagging cable — eps = 0.5, phi_a = 10 deg, lambda^2 = inf, h = 1, Gale xi = "
            "(-0.5000, 1.0000)"
            " — 4 checks, 1 failed.");
  EXPECT_EQ(paragraphs[1].text, " — ERROR: statics did not converge — 1 checks, 1 failed.");
  // Only gale-a has frequencies (in plane) and a forced response; stress-1 has neither.
  ASSERT_EQ(tables(out).size(), 2u);
}

TEST(ReportSections, FrequencyTableHasASolverColumnAndAPublishedColumnInTheScenesUnit) {
  Document out;
  add_scenes(out, document);
  const Table t = tables(out).at(0);
  EXPECT_EQ(t.css_class, "frequencies");
  // Gale's ratio, the published unit; airy (declined) has no column; published mode 3 adds a row.
  EXPECT_EQ(t.header, (Strings{"in-plane mode [gale]", "fe", "frobenius", "Gale 1976"}));
  EXPECT_EQ(
      t.rows,
      (Rows{{"1", "1.1", "1.1000001", "1.1"}, {"2", "2.2", "-", "-"}, {"3", "-", "-", "3.3"}}));
}

TEST(ReportSections, FrequencyUnitFollowsTagsWhenNothingIsPublished) {
  json run = document;
  json& scene = run["scenes"][0];
  scene["published"] = json::array();
  Document gale;
  add_scenes(gale, run);
  EXPECT_EQ(tables(gale).at(0).header[0], "in-plane mode [gale]");
  EXPECT_EQ(tables(gale).at(0).rows[0], (Strings{"1", "1.1", "1.1000001"}));
  scene["tags"] = json::array({"taut-inclined"});
  Document taut;
  add_scenes(taut, run);
  EXPECT_EQ(tables(taut).at(0).header[0], "in-plane mode [kL/pi]");
  EXPECT_EQ(tables(taut).at(0).rows[1], (Strings{"2", "0.6", "-"}));
  scene["tags"] = json::array();
  Document plain;
  add_scenes(plain, run);
  EXPECT_EQ(tables(plain).at(0).header[0], "in-plane mode [rad/s]");
  EXPECT_EQ(tables(plain).at(0).rows[0], (Strings{"1", "1", "1.0000001"}));
  // A published forced maximum says nothing about the unit of frequencies.
  scene["published"] = json::parse(
      R"([{"source": "x", "quantity": "forced_max_tension", "unit": "N", "modes": [1], "values": [1.0]}])");
  scene["tags"] = json::array({"gale"});
  Document forced;
  add_scenes(forced, run);
  EXPECT_EQ(tables(forced).at(0).header[0], "in-plane mode [gale]");
  // Hz when published in Hz.
  scene["published"] = json::parse(
      R"([{"source": "y", "quantity": "inplane_frequency", "unit": "Hz", "modes": [1], "values": [0.16]}])");
  Document hz;
  add_scenes(hz, run);
  EXPECT_EQ(tables(hz).at(0).header, (Strings{"in-plane mode [Hz]", "fe", "frobenius", "y"}));
  EXPECT_EQ(tables(hz).at(0).rows[0], (Strings{"1", "0.15915494", "0.15915495", "0.16"}));
}

TEST(ReportSections, ForcedTableGivesMaxTensionOverHOrTheDiagnostic) {
  Document out;
  add_scenes(out, document);
  const Table t = tables(out).at(1);
  EXPECT_EQ(t.css_class, "forced");
  EXPECT_EQ(t.header, (Strings{"forcing [rad/s]", "fe max|tau|/H"}));
  EXPECT_EQ(t.rows, (Rows{{"0.5", "1.5"}, {"1", "resonance"}}));  // 3 N / H = 2 N
}

}  // namespace
}  // namespace catena::internal
