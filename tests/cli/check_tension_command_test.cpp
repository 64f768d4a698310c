// SPDX-License-Identifier: MIT
// `catena check` on another program's dynamic tension, end to end through the binary, on the
// repository's mooring line (verification/scenes/physical/mooring-line-900m.toml, L = 1000 m): bad
// files exit 2 naming the row and the column and write nothing; a scene without [request.motion]
// is refused (exit 2) because Catena would not know the excitation.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/cli_support.hpp"

namespace catena::testing {
namespace {

namespace fs = std::filesystem;

const std::string kScene =
    std::string(CATENA_SOURCE_DIR) + "/verification/scenes/physical/mooring-line-900m.toml";
constexpr const char* kFolder = "catena_check_tension_test";

struct BadInput {
  const char* name;
  const char* csv;
  const char* expected;  // part of the message
};

TEST(CheckTensionCommand, BadInputExitsTwoNamingRowAndColumnAndWritesNothing) {
  const BadInput cases[] = {
      {"both", "s_m,node,nodes,tension_std_n\n0,0,3,5\n", "columns 's_m' and 'node' both given"},
      {"node-alone", "node,tension_std_n\n0,5\n", "column 'node' without column 'nodes'"},
      {"no-station", "tension_std_n\n5\n", "missing column 's_m'"},
      {"nan", "s_m,tension_std_n\n0,5\n10,nan\n", "row 2 (line 3), column 'tension_std_n'"},
      {"beyond-L", "s_m,tension_std_n\n0,5\n1000.5,5\n", "row 2 (line 3), column 's_m'"},
      {"node-range", "node,nodes,tension_std_n\n0,3,5\n3,3,5\n", "row 2 (line 3), column 'node'"},
      {"no-motion", "s_m,tension_std_n\n0,5\n1000,6\n", "the scene has no [request.motion]"},
  };
  for (const auto& c : cases) {
    const fs::path results = write_temp_file(kFolder, std::string(c.name) + ".csv", c.csv);
    const fs::path json = results.parent_path() / (std::string(c.name) + "-out.json");
    fs::remove(json);
    const CliRun run =
        run_cli("check " + results.string() + " --scene " + kScene + " --json " + json.string());
    EXPECT_EQ(run.exit_code, 2) << c.name << "\n" << run.output;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << c.name << "\n" << run.output;
    EXPECT_FALSE(fs::exists(json)) << c.name;
  }
}

TEST(CheckTensionCommand, ShapesAndReportDirectoryAreRefusedForATensionFile) {
  const fs::path results = write_temp_file(kFolder, "ok.csv", "s_m,tension_std_n\n0,5\n1000,6\n");
  const CliRun shapes =
      run_cli("check " + results.string() + " --scene " + kScene + " --shapes " + results.string());
  EXPECT_EQ(shapes.exit_code, 2) << shapes.output;
  EXPECT_NE(shapes.output.find("--shapes is for mode shapes"), std::string::npos) << shapes.output;
  const CliRun out = run_cli("check " + results.string() + " --scene " + kScene + " --out " +
                             (results.parent_path() / "report").string());
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("use --json"), std::string::npos) << out.output;
}

}  // namespace
}  // namespace catena::testing
