// SPDX-License-Identifier: MIT
// `catena solve` on a line over a seabed (docs/reference/scene-format.md, "Seabed"): the statics
// writes the seabed block; fe and shooting solve a line with contact, the other solvers decline it
// with their reason; a seabed the line does not touch changes no frequency; bad seabed input exits
// 2 naming the field.
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

constexpr const char* kFolder = "catena_seabed_cli_test";

std::string chain(double bx, double bz) {
  return "[cable]\nlength = 1000.0\nweight = 1200.0\nEA = 8.0e8\nmass = 150.0\nadded_mass = 20.0\n"
         "a = [0.0, -200.0]\nb = [" +
         std::to_string(bx) + ", " + std::to_string(bz) + "]\n";
}

const std::string kSeabed = "[seabed]\nz = -200.0\nfriction = 0.5\nstiffness = 3.0e6\n";
const std::string kStaticsOnly = "[request]\ninplane_modes = 0\noutofplane_modes = 0\n";
const std::string kModes = "[request]\ninplane_modes = 3\noutofplane_modes = 3\n";

TEST(SeabedCli, StaticsOnlySceneWritesTheSeabedBlock) {
  const fs::path scene =
      write_temp_file(kFolder, "statics.toml", chain(955.85, 0.0) + kSeabed + kStaticsOnly);
  const fs::path json_path = scene.parent_path() / "statics.json";
  const CliRun run = run_cli("solve " + scene.string() + " --json " + json_path.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("grounded length"), std::string::npos) << run.output;
  const auto document = nlohmann::json::parse(std::ifstream(json_path));
  const auto& scene_json = document["scenes"][0];
  const auto& seabed = scene_json["statics"]["seabed"];
  EXPECT_TRUE(seabed["contact"].get<bool>());
  EXPECT_EQ(seabed["friction"].get<double>(), 0.5);
  const double Lg = seabed["grounded_length_m"].get<double>();
  EXPECT_GT(Lg, 350.0);
  EXPECT_LT(Lg, 450.0);
  EXPECT_EQ(seabed["touchdown"]["z_m"].get<double>(), -200.0);
  EXPECT_EQ(seabed["anchor_vertical_force_n"].get<double>(), 0.0);
  const double H = seabed["fairlead_horizontal_force_n"].get<double>();
  EXPECT_NEAR(seabed["anchor_horizontal_force_n"].get<double>(), H - 0.5 * 1200.0 * Lg, 1e-6 * H);
  EXPECT_EQ(scene_json["problem"]["seabed"]["stiffness_n_per_m2"].get<double>(), 3.0e6);
}

// fe and shooting solve it (docs/explanation/methods/fe.md and
// docs/explanation/methods/shooting.md, "Seabed contact"); the others decline with a reason.
TEST(SeabedCli, FeAndShootingSolveALineWithContactAndTheOthersDecline) {
  const fs::path scene =
      write_temp_file(kFolder, "modes.toml", chain(955.85, 0.0) + kSeabed + kModes);
  const CliRun run = run_cli("solve " + scene.string() + " --verbose");
  EXPECT_NE(run.output.find("  fe: converged"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("in-plane: Converged: 3 of 3 in-plane modes"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("  shooting: converged"), std::string::npos) << run.output;
  for (const char* solver : {"frobenius", "asymptotic", "airy"}) {
    EXPECT_NE(run.output.find(std::string("  ") + solver + ": not applicable: "), std::string::npos)
        << run.output;
  }
  EXPECT_NE(run.output.find("has no model of seabed contact"), std::string::npos) << run.output;
}

// A taut line never touches: its frequencies are those without the seabed, to the last digit.
TEST(SeabedCli, SeabedWithoutContactChangesNoFrequency) {
  const fs::path with = write_temp_file(kFolder, "with.toml", chain(990.0, 0.0) + kSeabed + kModes);
  const fs::path without = write_temp_file(kFolder, "without.toml", chain(990.0, 0.0) + kModes);
  const CliRun a =
      run_cli("solve " + with.string() + " --solver shooting --json " + with.string() + ".json");
  const CliRun b = run_cli("solve " + without.string() + " --solver shooting --json " +
                           without.string() + ".json");
  ASSERT_EQ(a.exit_code, 0) << a.output;
  ASSERT_EQ(b.exit_code, 0) << b.output;
  const auto ja = nlohmann::json::parse(std::ifstream(with.string() + ".json"))["scenes"][0];
  const auto jb = nlohmann::json::parse(std::ifstream(without.string() + ".json"))["scenes"][0];
  EXPECT_FALSE(ja["statics"]["seabed"]["contact"].get<bool>());
  for (const char* plane : {"inplane", "outofplane"}) {
    const auto& ma = ja["solvers"]["shooting"][plane]["modes"];
    const auto& mb = jb["solvers"]["shooting"][plane]["modes"];
    ASSERT_EQ(ma.size(), 3u);
    ASSERT_EQ(ma.size(), mb.size());
    for (std::size_t i = 0; i < ma.size(); ++i) {
      EXPECT_EQ(ma[i]["omega_rad_s"].get<double>(), mb[i]["omega_rad_s"].get<double>());
    }
  }
}

struct BadSeabed {
  const char* name;
  std::string scene;
  const char* message;
};

TEST(SeabedCli, BadSeabedInputExitsTwoNamingTheField) {
  const BadSeabed cases[] = {
      {"anchor-below.toml", chain(955.85, 0.0) + "[seabed]\nz = -150.0\n" + kStaticsOnly,
       "end A must not be below the seabed"},
      {"fairlead-below.toml", chain(955.85, -250.0) + "[seabed]\nz = -200.0\n" + kStaticsOnly,
       "end B (the fairlead)"},
      {"friction.toml",
       chain(955.85, 0.0) + "[seabed]\nz = -200.0\nfriction = -0.1\n" + kStaticsOnly,
       "[seabed].friction"},
      {"stiffness.toml",
       chain(955.85, 0.0) + "[seabed]\nz = -200.0\nstiffness = -1.0\n" + kStaticsOnly,
       "[seabed].stiffness"},
      {"tangential.toml",
       chain(955.85, 0.0) + "[seabed]\nz = -200.0\ntangential_stiffness = -1.0\n" + kStaticsOnly,
       "[seabed].tangential_stiffness"},
      {"no-z.toml", chain(955.85, 0.0) + "[seabed]\nfriction = 0.1\n" + kStaticsOnly, "z"},
      {"gale.toml", "[gale]\nxi1 = -0.3\nxi2 = 0.3\n[seabed]\nz = 0.0\n" + kStaticsOnly,
       "[seabed] goes with"},
  };
  for (const BadSeabed& c : cases) {
    const fs::path scene = write_temp_file(kFolder, c.name, c.scene);
    const CliRun run = run_cli("solve " + scene.string());
    EXPECT_EQ(run.exit_code, 2) << c.name << "\n" << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.name << "\n" << run.output;
  }
}

}  // namespace
