// SPDX-License-Identifier: MIT
// `catena solve` with Morison drag and a motion request (docs/reference/scene-format.md, "Drag and
// dynamic tension in waves"): the scene is read and solved, the problem's drag and the request's
// motion are written to the JSON with each solver's dynamic tension (converged exactly when its
// residual is within the tolerance), the modes unchanged. Every bad value of the list
// exits 2 naming its field and writes no file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "cli/cli_support.hpp"

namespace {

namespace fs = std::filesystem;

using catena::testing::CliRun;
using catena::testing::run_cli;
using catena::testing::write_temp_file;

constexpr const char* kFolder = "catena_drag_cli_test";

const std::string kPlainCable =
    "[cable]\nlength = 1000.0\nweight = 1000.0\nEA = 5.0e8\nmass = 120.0\nadded_mass = 80.0\n"
    "a = [0.0, 0.0]\nb = [900.0, 300.0]\n";
const std::string kCable =
    kPlainCable + "diameter = 0.12\ndrag_normal = 2.4\ndrag_tangential = 1.15\n";
const std::string kModes = "[request]\ninplane_modes = 2\n";
const std::string kRao = "rao = { omega = [0.2, 0.6, 1.2], amplitude = [1.0, 0.8, 0.1] }\n";

TEST(DragCli, ADragSceneIsSolvedAndItsDynamicTensionPrintedAndWritten) {
  const fs::path scene =
      write_temp_file(kFolder, "regular.toml",
                      kCable + kModes +
                          "[request.motion]\ndirection = [1.0, 0.0]\namplitude = 2.0\n"
                          "periods = [8.0, 12.0]\n");
  const fs::path json_path = scene.parent_path() / "regular.json";
  const CliRun run =
      run_cli("solve " + scene.string() + " --verbose --solver fe --solver shooting --json " +
              json_path.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("drag: d = 0.12 m, Cd = 2.4, CdAx = 1.15"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("dynamic tension at the ends"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("T = 12 s fairlead max = mean + amplitude [N]"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("dynamic tension fixed point converged"), std::string::npos)
      << run.output;
  const auto document = nlohmann::json::parse(std::ifstream(json_path));
  const auto& scene_json = document["scenes"][0];
  EXPECT_EQ(scene_json["request"]["motion"]["periods_s"], nlohmann::json({8.0, 12.0}));
  EXPECT_EQ(scene_json["problem"]["cable"]["drag"]["drag_normal"].get<double>(), 2.4);
  for (const char* solver : {"fe", "shooting"}) {
    const auto& output = scene_json["solvers"][solver];
    ASSERT_EQ(output["dynamic_tension"].size(), 2u) << solver << ": one per period";
    // shooting at its default rtol may stall just above 1e-8 (methods/shooting.md): then it says
    // so.
    const auto& first = output["dynamic_tension"][0];
    EXPECT_EQ(first["converged"].get<bool>(), first["residual"].get<double>() <= 1e-8) << solver;
    if (std::string(solver) == "fe") EXPECT_TRUE(first["converged"].get<bool>());
    EXPECT_GT(output["dynamic_tension"][0]["fairlead"]["amplitude_n"].get<double>(), 0.0) << solver;
    EXPECT_EQ(output["inplane"]["modes"].size(), 2u) << solver << ": drag leaves the modes alone";
  }
}

TEST(DragCli, BadValuesExitTwoNamingTheFieldAndWriteNothing) {
  const std::string jonswap = kCable + kModes + "[request.motion]\n";
  const std::pair<std::string, std::string> cases[] = {
      {jonswap + "spectrum = { omega = [0.2, 0.5], density = [1.0, -0.5] }\n",
       "request.motion.spectrum.density[1]"},
      {jonswap + "jonswap = { hs = 0.0, tp = 10.0 }\n" + kRao, "[request.motion.jonswap].hs"},
      {jonswap + "jonswap = { hs = -3.0, tp = 10.0 }\n" + kRao, "[request.motion.jonswap].hs"},
      {jonswap + "jonswap = { hs = 3.0, tp = 10.0 }\n" +
           "rao = { omega = [0.2, 1.2, 0.6], amplitude = [1.0, 0.8, 0.1] }\n",
       "request.motion.rao.omega[2]"},
      {jonswap + "jonswap = { hs = 3.0, tp = 10.0 }\n" +
           "rao = { omega = [0.2, 0.6, 1.2], amplitude = [1.0, inf, 0.1] }\n",
       "[request.motion.rao].amplitude"},
      {jonswap + "amplitude = 1.0\nperiods = [10.0, -8.0]\n", "[request.motion].periods"},
      {jonswap + "amplitude = 1.0\nperiods = [0.0]\n", "[request.motion].periods"},
      {kPlainCable + "diameter = 0.12\ndrag_normal = -1.0\n", "[cable].drag_normal"},
      {"[cable]\nlength = 10.0\nweight = 1.0\nEA = 1e6\nmass = 1.0\na = [0.0, 0.0]\n"
       "b = [8.0, 1.0]\ndiameter = 0.0\n",
       "[cable].diameter"},
      {"[cable]\nlength = 10.0\nweight = 1.0\nEA = 1e6\nmass = 1.0\na = [0.0, 0.0]\n"
       "b = [8.0, 1.0]\ndiameter = -0.1\n",
       "[cable].diameter"},
      {jonswap + "spectrum = { omega = [0.2, 0.5, 0.8], density = [1.0, 0.5] }\n",
       "request.motion.spectrum.density"},
      {jonswap + "jonswap = { hs = 3.0, tp = 10.0 }\n" +
           "rao = { omega = [0.2, 0.6, 1.2], amplitude = [1.0, 0.5] }\n",
       "request.motion.rao.amplitude"},
      {jonswap + "jonswap = { hs = 3.0, tp = 10.0 }\n" + kRao +
           "spectrum = { omega = [0.2, 0.5], density = [1.0, 0.5] }\n",
       "give either spectrum or jonswap"},
  };
  int index = 0;
  for (const auto& [text, field] : cases) {
    const std::string name = "bad" + std::to_string(index++);
    const fs::path scene = write_temp_file(kFolder, name + ".toml", text);
    const fs::path json_path = scene.parent_path() / (name + ".json");
    fs::remove(json_path);
    const CliRun run = run_cli("solve " + scene.string() + " --json " + json_path.string());
    EXPECT_EQ(run.exit_code, 2) << field << "\n" << run.output;
    EXPECT_NE(run.output.find(field), std::string::npos) << field << "\n" << run.output;
    EXPECT_FALSE(fs::exists(json_path)) << field;
  }
}

}  // namespace
