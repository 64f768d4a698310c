// SPDX-License-Identifier: MIT
// The report's data layer: cells of the results JSON as text, and the CSV tables written beside the
// report (frequencies, checks, published) read back with csv_table; the benchmark baseline of time
// against error reduced to the fastest time per accuracy target.
#include "io/report/report_data.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/csv_table.hpp"
#include "io/report/report_test_support.hpp"

namespace catena::internal {
namespace {

namespace fs = std::filesystem;
using Strings = std::vector<std::string>;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  return dir;
}

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

TEST(ReportData, NumberTextFormatsNumbersAndDashesTheRest) {
  EXPECT_EQ(number_text(json(1.23456789)), "1.23457");
  EXPECT_EQ(number_text(json(3)), "3");
  EXPECT_EQ(number_text(json(0.0434), "{:.3e}"), "4.340e-02");
  EXPECT_EQ(number_text(json(nullptr)), "-");
  EXPECT_EQ(number_text(json("1.5")), "-");  // text is not a number, even when it reads as one
  EXPECT_EQ(number_text(json::array()), "-");
}

TEST(ReportData, ListOrEmptyGivesTheListItselfOrAnEmptyArray) {
  const json scene = {{"published", json::array({1, 2})}};
  EXPECT_EQ(&list_or_empty(scene, "published"), &scene.at("published"));  // a reference, not a copy
  EXPECT_TRUE(list_or_empty(scene, "checks").is_array());
  EXPECT_TRUE(list_or_empty(scene, "checks").empty());
}

TEST(ReportData, HasTagLooksInTheScenesTags) {
  const json document = testing::synthetic_results();
  EXPECT_TRUE(has_tag(document["scenes"][0], "gale"));
  EXPECT_FALSE(has_tag(document["scenes"][0], "stress"));
  EXPECT_TRUE(has_tag(document["scenes"][1], "stress"));
  EXPECT_FALSE(has_tag(document["scenes"][1], "stres"));  // whole tags only
  EXPECT_FALSE(has_tag(json::object(), "gale"));          // no tags at all
}

class DataTables : public ::testing::Test {
 protected:
  void SetUp() override {
    // One directory per test (ctest runs them in parallel); the nested ones are created as needed.
    dir = fresh_dir(std::string("catena_report_data_test_") +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name()) /
          "nested" / "data";
    write_data_tables(testing::synthetic_results(), dir);
  }
  fs::path dir;
};

TEST_F(DataTables, FrequenciesHaveOneRowPerModeOfEverySolver) {
  const CsvTable t = read_csv_table(dir / "frequencies.csv");
  EXPECT_EQ(t.columns, (Strings{"scene", "solver", "plane", "mode", "omega_rad_s", "frequency_hz",
                                "k_l_over_pi", "gale_ratio", "relative_error_estimate"}));
  ASSERT_FALSE(t.comments.empty());
  ASSERT_EQ(t.rows.size(), 3u);  // fe 2 + frobenius 1; airy declined, stress-1 has no modes
  EXPECT_EQ(t.text(0, "scene"), "gale-a");
  EXPECT_EQ(t.text(0, "solver"), "fe");
  EXPECT_EQ(t.text(0, "plane"), "inplane");
  EXPECT_EQ(t.text(1, "mode"), "2");
  EXPECT_EQ(t.text(2, "solver"), "frobenius");
  // Numbers to 17 digits: they read back exactly.
  EXPECT_EQ(*t.number(0, "frequency_hz"), 0.15915494309189535);
  EXPECT_EQ(*t.number(2, "omega_rad_s"), 1.0000001);
  EXPECT_EQ(*t.number(1, "relative_error_estimate"), 2e-10);
  // null is an empty cell, i.e. a missing value.
  EXPECT_FALSE(t.number(2, "relative_error_estimate").has_value());
}

TEST_F(DataTables, ChecksHaveEveryCheckOfEveryScene) {
  const CsvTable t = read_csv_table(dir / "checks.csv");
  EXPECT_EQ(t.columns, (Strings{"scene", "check", "compare", "plane", "mode", "value_a", "value_b",
                                "measured", "tolerance", "verdict", "detail"}));
  ASSERT_EQ(t.rows.size(), 5u);
  EXPECT_EQ(t.rows[0],
            (Strings{"gale-a", "published", "fe vs Gale 1976", "inplane", "1", "1.1000000000000001",
                     "1.2", "0.089999999999999997", "0.01", "SOURCE", "misprint"}));
  EXPECT_EQ(t.text(3, "value_a"), "");  // null
  EXPECT_EQ(t.text(4, "scene"), "stress-1");
  EXPECT_EQ(t.text(4, "verdict"), "FAIL");
}

TEST_F(DataTables, PublishedHasOnlyThePublishedComparisons) {
  const CsvTable t = read_csv_table(dir / "published.csv");
  EXPECT_EQ(t.columns, (Strings{"scene", "compare", "plane", "mode", "ours", "printed",
                                "abs_difference", "tolerance", "verdict", "detail"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.text(0, "compare"), "fe vs Gale 1976");
  EXPECT_EQ(*t.number(0, "ours"), 1.1);
  EXPECT_EQ(*t.number(0, "printed"), 1.2);
  EXPECT_EQ(t.text(1, "compare"), "frobenius vs Gale 1976");
  EXPECT_EQ(t.text(1, "verdict"), "PASS");
  EXPECT_EQ(t.text(1, "detail"), "");
}

TEST(ReportData, TimeToAccuracyKeepsTheFastestSettingPerTarget) {
  const fs::path csv = write_file("catena_report_timing.csv",
                                  "# time vs error, against a reference.\n# machine\n"
                                  "scene,solver,setting,time_s,max_rel_error,status\n"
                                  "\"case, one\",fe,N=10,1e-3,1e-4,converged\n"
                                  "\"case, one\",fe,N=20,2e-3,1e-7,converged\n"
                                  "\"case, one\",fe,N=5,5e-4,1e-2,converged\n"
                                  "\"case, one\",airy,-,1e-4,nan,not-applicable\n");
  const TimeToAccuracy timing = read_time_to_accuracy(csv);
  // The first comment line says what the error is measured against; the report quotes it.
  EXPECT_EQ(timing.description, "time vs error, against a reference");
  ASSERT_EQ(timing.cases, std::vector<std::string>{"case, one"});
  const auto& fe = timing.best_time_s.at("case, one").at("fe");
  EXPECT_EQ(fe.at(1e-3), 1e-3);  // N=10 reaches 1e-3 and is faster than N=20
  EXPECT_EQ(fe.at(1e-6), 2e-3);
  EXPECT_FALSE(fe.count(1e-9));
  EXPECT_FALSE(timing.best_time_s.at("case, one").count("airy"));
  EXPECT_TRUE(read_time_to_accuracy("/nonexistent.csv").cases.empty());
}

TEST(ReportData, TimeToAccuracyCountsAnErrorOnTheTargetAndKeepsCasesInFileOrder) {
  const fs::path csv = write_file("catena_report_timing_order.csv",
                                  "scene,solver,setting,time_s,max_rel_error,status\n"
                                  "zeta,shooting,rtol=1e-9,0.5,1e-9,converged\n"
                                  "alpha,fe,N=10,0.1,,no-convergence\n"
                                  "zeta,shooting,rtol=1e-6,0.25,1e-6,converged\n");
  const TimeToAccuracy timing = read_time_to_accuracy(csv);
  EXPECT_EQ(timing.cases, (Strings{"zeta", "alpha"}));  // file order, not sorted
  const auto& shooting = timing.best_time_s.at("zeta").at("shooting");
  EXPECT_EQ(shooting.at(1e-9), 0.5);  // an error of exactly 1e-9 reaches the 1e-9 target
  EXPECT_EQ(shooting.at(1e-6), 0.25);
  EXPECT_EQ(shooting.at(1e-3), 0.25);
  EXPECT_FALSE(timing.best_time_s.count("alpha"));  // no error, no target reached
}

TEST(ReportData, MalformedBaselineIsAParseError) {
  EXPECT_THROW(read_time_to_accuracy(
                   write_file("catena_report_timing_ragged.csv",
                              "scene,solver,setting,time_s,max_rel_error,status\na,fe,N\n")),
               ParseError);
  EXPECT_THROW(read_time_to_accuracy(
                   write_file("catena_report_timing_columns.csv", "scene,solver,time\na,fe,1\n")),
               ParseError);
  EXPECT_THROW(read_time_to_accuracy(write_file("catena_report_timing_number.csv",
                                                "scene,solver,setting,time_s,max_rel_error,status\n"
                                                "a,fe,N=1,fast,1e-4,converged\n")),
               ParseError);
}

}  // namespace
}  // namespace catena::internal
