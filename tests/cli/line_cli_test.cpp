// SPDX-License-Identifier: MIT
// `catena solve` on general lines (docs/reference/scene-format.md, "General lines", "Statics-only
// scenes"): a statics-only scene prints the line's table, writes the per-node statics to JSON and
// runs no solver; bad line input exits 2 naming the entry and field; an analytic solver declines a
// line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_support.hpp"

namespace {

namespace fs = std::filesystem;

using catena::testing::CliRun;
using catena::testing::run_cli;

fs::path write_scene(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "catena_line_cli_test";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

const std::string kLine = R"(
[line]
a = [0.0, -100.0]
b = [200.0, 0.0]
[[line.segments]]
length = 120.0
weight = 900.0
EA = 5e8
mass = 100.0
[[line.segments]]
length = 130.0
weight = 0.0
EA = 1e8
mass = 10.0
[[line.points]]
s = 60.0
mass = 1000.0
weight = 2e4
)";

TEST(LineCli, StaticsOnlySceneWritesNodesAndRunsNoSolver) {
  const fs::path scene =
      write_scene("statics.toml", kLine + "[request]\ninplane_modes = 0\noutofplane_modes = 0\n");
  const fs::path json_path = scene.parent_path() / "statics.json";
  // The statics at every joint and point is the problem's description: --verbose.
  const CliRun run = run_cli("solve " + scene.string() + " --verbose --json " + json_path.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("joint 1"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("point 0"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("lowest point"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("solver "), std::string::npos) << run.output;
  const auto document = nlohmann::json::parse(std::ifstream(json_path));
  const auto& result = document["scenes"][0];
  EXPECT_TRUE(result["solvers"].empty());
  const auto& nodes = result["statics"]["nodes"];
  ASSERT_EQ(nodes.size(), 2u);
  EXPECT_EQ(nodes[0]["kind"], "point");
  EXPECT_EQ(nodes[1]["kind"], "joint");
  // The point's weight is the jump of V across it.
  EXPECT_NEAR(nodes[0]["vertical_force_after_n"].get<double>() -
                  nodes[0]["vertical_force_before_n"].get<double>(),
              2e4, 1e-6);
  EXPECT_EQ(result["statics"]["segments"]["stretched_length_m"].size(), 2u);
  EXPECT_TRUE(result["groups"]["eps"].is_null());
}

TEST(LineCli, BadLineInputExitsTwoNamingTheField) {
  const fs::path overlapping = write_scene("overlap.toml", kLine + "[[line.points]]\ns = 60.0\n");
  CliRun run = run_cli("solve " + overlapping.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("line.points[1].s"), std::string::npos) << run.output;
  std::string zero = kLine;
  zero.replace(zero.find("length = 130.0"), 14, "length = 0.0");
  run = run_cli("solve " + write_scene("zero.toml", zero).string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("line.segments[1]"), std::string::npos) << run.output;
  std::string short_line = kLine;
  short_line.replace(short_line.find("b = [200.0, 0.0]"), 16, "b = [300.0, 0.0]");
  for (const char* ea : {"EA = 5e8", "EA = 1e8"})
    short_line.replace(short_line.find(ea), std::string(ea).size(), "EA = \"inf\"");
  run = run_cli("solve " + write_scene("short.toml", short_line).string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("too short"), std::string::npos) << run.output;
}

// No equilibrium in tension (a weightless rope between a chain and a buoyant rope, ends too
// close for it to be taut) is the input's fault, exit 2 like every other "No static equilibrium"
// (issue 32: it was exit 3, a numerical failure).
TEST(LineCli, NoEquilibriumInTensionExitsTwo) {
  const std::string segment = "[[line.segments]]\nEA = 1e7\nmass = 1.0\n";
  const fs::path scene = write_scene(
      "no-equilibrium.toml", "[line]\na = [0.0, 0.0]\nb = [50.0, 0.0]\n" + segment +
                                 "length = 10.0\nweight = 10.0\n" + segment +
                                 "length = 100.0\nweight = 0.0\n" + segment +
                                 "length = 10.0\nweight = -10.0\n[request]\ninplane_modes = 1\n");
  const CliRun run = run_cli("solve " + scene.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("line.segments: No static equilibrium in tension"), std::string::npos)
      << run.output;
}

TEST(LineCli, AnalyticSolversDeclineALineWithTheirReason) {
  const fs::path scene = write_scene(
      "modes.toml", kLine + "[request]\ninplane_modes = 2\n[solvers]\nfrobenius = {}\n");
  const CliRun run = run_cli("solve " + scene.string());
  EXPECT_NE(run.output.find("frobenius: not applicable: "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("one uniform cable"), std::string::npos) << run.output;
}

}  // namespace
