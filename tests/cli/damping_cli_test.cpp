// SPDX-License-Identifier: MIT
// `catena solve` on a damped line (docs/reference/scene-format.md, "Damping"): the problem's
// damping is written to the JSON and every mode carries its decay rate and damping ratio; bad
// damping exits 2 naming the field, and writes no file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_support.hpp"

namespace {

namespace fs = std::filesystem;

using catena::testing::CliRun;
using catena::testing::run_cli;
using catena::testing::write_temp_file;

constexpr const char* kFolder = "catena_damping_cli_test";

const std::string kCable =
    "[cable]\nlength = 1000.0\nweight = 1000.0\nEA = 5.0e8\nmass = 120.0\nadded_mass = 80.0\n"
    "a = [0.0, 0.0]\nb = [900.0, 300.0]\n";
const std::string kRequest = "[request]\ninplane_modes = 2\noutofplane_modes = 2\n";

TEST(DampingCli, AnUndampedLineHasZeroDecayInEveryModeAndNoDampingBlock) {
  const fs::path scene = write_temp_file(kFolder, "undamped.toml", kCable + kRequest);
  const fs::path json_path = scene.parent_path() / "undamped.json";
  const CliRun run = run_cli("solve " + scene.string() + " --json " + json_path.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto document = nlohmann::json::parse(std::ifstream(json_path));
  const auto& scene_json = document["scenes"][0];
  EXPECT_FALSE(scene_json["problem"]["cable"].contains("damping"));
  int modes = 0;
  for (const auto& [solver, output] : scene_json["solvers"].items()) {
    if (!output.contains("inplane")) continue;
    for (const auto& mode : output["inplane"]["modes"]) {
      EXPECT_EQ(mode["decay_rate_1_s"].get<double>(), 0.0) << solver;
      EXPECT_EQ(mode["damping_ratio"].get<double>(), 0.0) << solver;
      ++modes;
    }
  }
  EXPECT_GT(modes, 0);
}

TEST(DampingCli, TheDampedProblemIsWrittenWithItsCoefficients) {
  const fs::path scene = write_temp_file(
      kFolder, "damped.toml",
      kCable + "damping_tangential = 12.0\ndamping_normal = 200.0\naxial_damping = 1e7\n" +
          kRequest);
  const fs::path json_path = scene.parent_path() / "damped.json";
  const CliRun run = run_cli("solve " + scene.string() + " --json " + json_path.string());
  ASSERT_NE(run.exit_code, 2) << run.output;
  const auto document = nlohmann::json::parse(std::ifstream(json_path));
  const auto& damping = document["scenes"][0]["problem"]["cable"]["damping"];
  EXPECT_EQ(damping["tangential_n_s_per_m2"].get<double>(), 12.0);
  EXPECT_EQ(damping["normal_n_s_per_m2"].get<double>(), 200.0);
  EXPECT_EQ(damping["axial_n_s"].get<double>(), 1e7);
}

TEST(DampingCli, BadDampingExitsTwoNamingTheFieldAndWritesNothing) {
  const std::pair<std::string, std::string> cases[] = {
      {kCable + "damping_normal = -5.0\n", "damping_normal"},
      {kCable + "damping_tangential = inf\n", "damping_tangential"},
      {"[cable]\nlength = 10.0\nweight = 1.0\nEA = \"inf\"\nmass = 1.0\na = [0.0, 0.0]\n"
       "b = [8.0, 1.0]\naxial_damping = 1.0\n",
       "axial_damping"},
  };
  int index = 0;
  for (const auto& [text, field] : cases) {
    const fs::path scene = write_temp_file(kFolder, "bad" + std::to_string(index) + ".toml", text);
    const fs::path json_path = scene.parent_path() / ("bad" + std::to_string(index++) + ".json");
    fs::remove(json_path);
    const CliRun run = run_cli("solve " + scene.string() + " --json " + json_path.string());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(field), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(json_path)) << field;
  }
}

}  // namespace
