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
#include "io/report/results_layout.hpp"
#include "report_test_support.hpp"

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

// issue 32, item 9: results files that are JSON but not what `catena verify` writes were internal
// errors (exit 3). Each is now a catena::Error naming the file and the place.
TEST(ReportWriter, MalformedResultsFilesAreBadInputNamingThePlace) {
  const fs::path dir = fs::temp_directory_path() / "catena_report_malformed";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string meta = R"("catena": {"version": "1"}, )";
  const std::string scene =
      R"({"name": "s", "error": null, "checks": [], "groups": {"eps": 0.1, "chord_angle_deg": 0,)"
      R"( "lambda2": 1, "mass_ratio": 1}, "statics": {}, "solvers": )";
  const std::pair<std::string, std::string> cases[] = {
      {R"({"scenes": null})", "\"catena\""},
      {"{" + meta + R"("scenes": null})", "scenes: not an array"},
      {"{" + meta + R"("scenes": [{}]})", "scenes[0]: no \"name\""},
      {"{" + meta + R"("scenes": [)" + scene + R"({"fe": null}}]})",
       "scenes[0].solvers.fe: not an object"},
      {"{\"scenes\": " + std::string(200000, '[') + std::string(200000, ']') + "}",
       "nested deeper than"},
      {"{" + meta + R"("scenes": [)" + scene +
           R"({"fe": {"summary": {}, "inplane": {"modes": [1]}}}}]})",
       "scenes[0].solvers.fe.inplane.modes[0]: not an object"},
      {"{" + meta + R"("scenes": [)" + scene +
           R"({}, "published": [{"quantity": "inplane_frequency", "modes": [-1], "values": [1]}]}]})",
       "published[0].modes: -1 is not a whole number"},
      {"{" + meta + R"("scenes": [], "scenes": []})", "key 'scenes' given twice"},
      {"{" + meta + R"("scenes": [)" + scene + R"({}, "tags": 3}]})", "wrong type"},
  };
  ReportOptions options;
  options.out_dir = dir / "out";
  options.figures = false;
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    const fs::path path = dir / ("case" + std::to_string(i) + ".json");
    std::ofstream(path) << cases[i].first;
    try {
      write_report(path, options);
      ADD_FAILURE() << "case " << i << " was read";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(cases[i].second), std::string::npos)
          << "case " << i << ": " << error.what();
    }
  }
}

// The layout check accepts the hand-written document of the section tests (every verdict, a
// declined solver, a scene error, published entries) and a document Catena wrote (above).
TEST(ReportWriter, LayoutCheckAcceptsTheHandWrittenResults) {
  EXPECT_NO_THROW(internal::check_results_layout(testing::synthetic_results(), "synthetic"));
}

}  // namespace
}  // namespace catena
