// SPDX-License-Identifier: MIT
// write_report on a small results JSON: the Markdown and HTML reports, the data tables read back
// with csv_table, the figure note when figures are off, and a clear error for a bad input file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/io/csv_table.hpp"
#include "catena/io/json_writer.hpp"
#include "catena/io/report.hpp"
#include "catena/io/scene_reader.hpp"
#include "catena/io/tolerance_reader.hpp"

namespace catena {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path results_json(const fs::path& dir) {
  SceneRunOptions options;
  options.tolerances = builtin_tolerance_table();
  options.only_solvers = {"fe", "shooting"};
  const Scene scene =
      parse_scene_text(
          "name = \"report, test\"\n[cable]\nlength = 10.0\nweight = 1.0\nEA = 1e6\nmass = 1.0\n"
          "a = [0.0, 0.0]\nb = [8.0, 1.0]\n[request]\ninplane_modes = 2\n",
          "r.toml")
          .front();
  fs::create_directories(dir);
  write_results_json(dir / "report.json", {run_scene(scene, options)});
  return dir / "report.json";
}

TEST(ReportWriter, WritesMarkdownHtmlAndDataTables) {
  const fs::path dir = fs::temp_directory_path() / "catena_report_test";
  fs::remove_all(dir);
  ReportOptions options;
  options.out_dir = dir;
  options.figures = false;
  const ReportFiles files = write_report(results_json(dir), options);
  const std::string md = read(files.markdown);
  EXPECT_NE(md.find("# Catena verification report"), std::string::npos);
  EXPECT_NE(md.find("### report, test"), std::string::npos);
  EXPECT_NE(md.find("figures not drawn (--no-figures)"), std::string::npos);
  EXPECT_EQ(files.figures, 0);
  EXPECT_NE(read(files.html).find("<!DOCTYPE html>"), std::string::npos);
  // The scene name holds a comma: the CSV quotes it and reads back whole.
  const CsvTable frequencies = read_csv_table(files.data_dir / "frequencies.csv");
  ASSERT_EQ(frequencies.rows.size(), 4u);  // 2 solvers x 2 modes
  EXPECT_EQ(frequencies.text(0, "scene"), "report, test");
  EXPECT_GT(*frequencies.number(0, "omega_rad_s"), 0.0);
  const CsvTable checks = read_csv_table(files.data_dir / "checks.csv");
  EXPECT_FALSE(checks.rows.empty());
}

TEST(ReportWriter, BadResultsFileIsAParseError) {
  const fs::path bad = fs::temp_directory_path() / "catena_report_bad.json";
  std::ofstream(bad) << "{\"not\": \"results\"}";
  ReportOptions options;
  options.out_dir = fs::temp_directory_path() / "catena_report_bad";
  options.figures = false;
  EXPECT_THROW(write_report(bad, options), ParseError);
  EXPECT_THROW(write_report("/nonexistent.json", options), ParseError);
}

}  // namespace
}  // namespace catena
