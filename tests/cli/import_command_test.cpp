// SPDX-License-Identifier: MIT
// `catena import moordyn` end to end on decks written for these tests (MoorDyn v1 and v2
// layouts, not copies of published decks): what each line becomes, the conversion of MoorDyn's
// quantities, a converted [cable] scene that `catena solve` solves, and bad decks (exit 2 naming
// the line, nothing written).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "catena/core/types.hpp"
#include "cli/cli_support.hpp"

namespace catena::testing {
namespace {

namespace fs = std::filesystem;

const std::string kV2Deck =
    std::string(CATENA_SOURCE_DIR) + "/docs/examples/moordyn-v2-semitaut.txt";
constexpr const char* kFolder = "catena_import_test";

// v1 layout (LINE DICTIONARY, NODE PROPERTIES with forces, LINE PROPERTIES with NodeAnch/NodeFair,
// SOLVER OPTIONS with rhoW and g): a catenary resting on the seabed, and a bridle of three lines
// meeting at a connect point.
const std::string kV1Deck = R"(MoorDyn input file, v1 layout, written for Catena's tests
---------------------- LINE DICTIONARY ---------------------------------
LineType  Diam   MassDenInAir  EA      BA/-zeta  Can  Cat  Cdn  Cdt
(-)       (m)    (kg/m)        (N)     (Pa-s/-)  (-)  (-)  (-)  (-)
chain     0.1    100.0         8.0e8   -0.8      0.8  0.25 2.0  0.4
---------------------- NODE PROPERTIES ---------------------------------
Node  Type     X       Y     Z       M    V    FX  FY  FZ  CdA  CA
(-)   (-)      (m)     (m)   (m)     (kg) (m^3) (kN) (kN) (kN) (m^2) (-)
1     Fix      -600.0  0.0   -200.0  0    0    0   0   0   0    0
2     Vessel   0.0     0.0   -10.0   0    0    0   0   0   0    0
3     Fix      300.0   500.0 -200.0  0    0    0   0   0   0    0
4     Connect  100.0   200.0 -100.0  0    0    0   0   0   0    0
5     Vessel   5.0     10.0  -10.0   0    0    0   0   0   0    0
6     Vessel   10.0    5.0   -10.0   0    0    0   0   0   0    0
---------------------- LINE PROPERTIES ---------------------------------
Line  LineType  UnstrLen  NumSegs  NodeAnch  NodeFair  Flags/Outputs
(-)   (-)       (m)       (-)      (-)       (-)       (-)
1     chain     700.0     20       1         2         -
2     chain     450.0     20       3         4         -
3     chain     120.0     10       4         5         -
4     chain     120.0     10       4         6         -
---------------------- SOLVER OPTIONS ----------------------------------
0.001    dtM       - time step (s)
1020     rhoW      - water density (kg/m^3)
9.81     g         - gravity (m/s^2)
200      WtrDpth   - water depth (m)
2.0e6    kBot      - bottom stiffness (Pa/m)
------------------------- need this line -------------------------------
)";

std::string read_text(const fs::path& path) {
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

// The first value of `key` in a scene's text (after "\nkey = ").
double value_of(const std::string& text, const std::string& key, std::size_t from = 0) {
  const auto at = text.find("\n" + key + " = ", from);
  if (at == std::string::npos) return NAN;
  return std::stod(text.substr(at + key.size() + 4));
}

// Rounding of the conversion's arithmetic (a few operations in double).
constexpr double kRelTolConversion = 1e-14;

TEST(ImportCommand, V2DeckConvertsEachLineOrSaysWhyNot) {
  const fs::path out = fs::temp_directory_path() / kFolder / "v2";
  fs::remove_all(out);
  const CliRun run = run_cli("import moordyn " + kV2Deck + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  // Line 1: one uniform, taut line: a [cable] scene with the deck's seabed (it stays off it).
  const fs::path single = out / "moordyn-v2-semitaut-line-1.toml";
  const std::string text = read_text(single);
  EXPECT_NE(text.find("[cable]"), std::string::npos) << text;
  EXPECT_NE(text.find("\n[seabed]"), std::string::npos) << text;
  EXPECT_EQ(text.find("Needs:"), std::string::npos) << text;
  EXPECT_NE(run.output.find("moordyn-v2-semitaut-line-1.toml  [cable] + [seabed]: off the seabed"),
            std::string::npos)
      << run.output;
  EXPECT_NE(text.find("b = [800.0, -20.0]"), std::string::npos) << text;
  const double weight = (35.0 - 1025.0 * kPi / 4.0 * 0.04) * 9.80665;  // (MassDen - rho pi/4 d^2) g
  EXPECT_NEAR(value_of(text, "weight"), weight, kRelTolConversion * weight) << text;
  // Diam, Cd, CdAx, CaAx of type poly; BA = -1: zeta = 1 of MoorDyn's segment critical damping,
  // 1 (840 m / 40 segments) sqrt(EA MassDen) N s.
  EXPECT_EQ(value_of(text, "diameter"), 0.2) << text;
  EXPECT_EQ(value_of(text, "drag_normal"), 2.0) << text;
  EXPECT_EQ(value_of(text, "drag_tangential"), 0.4) << text;
  EXPECT_EQ(value_of(text, "added_mass_tangential"), 0.0) << text;
  const double ba = 840.0 / 40.0 * std::sqrt(1.5e8 * 35.0);
  EXPECT_NEAR(value_of(text, "axial_damping"), ba, kRelTolConversion * ba) << text;
  EXPECT_NE(text.find("BA = -1 is a damping ratio"), std::string::npos) << text;
  EXPECT_EQ(value_of(text, "water_density"), 1025.0) << text;
  EXPECT_EQ(value_of(text, "gravity"), 9.80665) << text;
  const CliRun solved = run_cli("solve " + single.string() + " --solver shooting --solver fe");
  EXPECT_EQ(solved.exit_code, 0) << solved.output;
  // Lines 2 and 3: chain and wire in series through a free point with a clump: one [line].
  const std::string chain = read_text(out / "moordyn-v2-semitaut-line-2-3.toml");
  EXPECT_NE(chain.find("[[line.segments]]"), std::string::npos) << chain;
  EXPECT_NE(chain.find("s = 300.0"), std::string::npos) << chain;
  const double clump = (20000.0 - 1025.0 * 2.0) * 9.80665;  // (M - rho V) g
  EXPECT_NEAR(value_of(chain, "weight", chain.rfind("[[line.points]]")), clump,
              kRelTolConversion * clump)
      << chain;
  EXPECT_NE(run.output.find("moordyn-v2-semitaut-line-2-3.toml  [line] 2 segments, 1 point + "
                            "[seabed]: "),
            std::string::npos)
      << run.output;
  // The chain type's CaAx = 0.5 on the first segment: rho_w CaAx pi/4 Diam^2.
  const double chain_ma_t = 0.5 * 1025.0 * kPi / 4.0 * 0.15 * 0.15;
  EXPECT_NEAR(value_of(chain, "added_mass_tangential"), chain_ma_t, kRelTolConversion * chain_ma_t)
      << chain;
  // Line 4 hangs from a body.
  EXPECT_NE(run.output.find("not converted: attached to a body at point 7"), std::string::npos)
      << run.output;
}

TEST(ImportCommand, V1DeckUsesItsOptionsAndRefusesABridle) {
  const fs::path deck = write_temp_file(kFolder, "v1.dat", kV1Deck);
  const fs::path out = deck.parent_path() / "v1";
  fs::remove_all(out);
  const CliRun run = run_cli("import moordyn " + deck.string() + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string text = read_text(out / "v1-line-1.toml");
  // rhoW = 1020 and g = 9.81 from the options; Can = 0.8 from the v1 column.
  const double weight = (100.0 - 1020.0 * kPi / 4.0 * 0.01) * 9.81;
  const double added_mass = 0.8 * 1020.0 * kPi / 4.0 * 0.01;
  EXPECT_NEAR(value_of(text, "weight"), weight, kRelTolConversion * weight) << text;
  EXPECT_NEAR(value_of(text, "added_mass"), added_mass, kRelTolConversion * added_mass) << text;
  // v1 columns: Cdn = 2.0, Cdt = 0.4, Cat = 0.25; BA = -0.8 with NumSegs = 20 over 700 m; the
  // options' water into [environment].
  EXPECT_EQ(value_of(text, "diameter"), 0.1) << text;
  EXPECT_EQ(value_of(text, "drag_normal"), 2.0) << text;
  EXPECT_EQ(value_of(text, "drag_tangential"), 0.4) << text;
  const double added_mass_tangential = 0.25 * 1020.0 * kPi / 4.0 * 0.01;
  EXPECT_NEAR(value_of(text, "added_mass_tangential"), added_mass_tangential,
              kRelTolConversion * added_mass_tangential)
      << text;
  const double ba = 0.8 * 700.0 / 20.0 * std::sqrt(8.0e8 * 100.0);
  EXPECT_NEAR(value_of(text, "axial_damping"), ba, kRelTolConversion * ba) << text;
  EXPECT_EQ(value_of(text, "water_density"), 1020.0) << text;
  EXPECT_EQ(value_of(text, "gravity"), 9.81) << text;
  // 700 m of chain over 600 m x 190 m rests on the seabed at z = -200: [cable] with [seabed].
  EXPECT_NE(text.find("\n[seabed]"), std::string::npos) << text;
  EXPECT_NE(text.find("stiffness = 200000.0"), std::string::npos) << text;  // kBot 2e6 Pa/m x 0.1 m
  // The importer solved its statics with the seabed and says how much of it rests there.
  EXPECT_NE(run.output.find("v1-line-1.toml  [cable] + [seabed]: grounded "), std::string::npos)
      << run.output;
  EXPECT_NE(text.find("# Statics with the seabed: H = "), std::string::npos) << text;
  // The rest of the deck: each option with what became of it, under the table.
  EXPECT_NE(run.output.find("What became of the rest of the deck:"), std::string::npos);
  EXPECT_NE(run.output.find("option dtM = 0.001: ignored - MoorDyn's time integration"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("option kBot = 2.0e6: used - [seabed] stiffness = kBot Diam"),
            std::string::npos)
      << run.output;
  // The [seabed] table it writes is read: the statics lays part of the chain on the seabed.
  const CliRun solve = run_cli("solve " + (out / "v1-line-1.toml").string() + " --solver fe");
  EXPECT_EQ(solve.exit_code, 0) << solve.output;
  EXPECT_NE(solve.output.find("grounded length"), std::string::npos) << solve.output;
  for (const char* line : {"2 ", "3 ", "4 "}) {
    EXPECT_NE(
        run.output.find(std::string(line) + "         not converted: 3 lines meet at free point 4"),
        std::string::npos)
        << run.output;
  }
}

// A positive BA is the Kelvin-Voigt coefficient itself; a BA that is not one number (a curve file,
// a viscoelastic pair) cannot be one coefficient: that line is not converted, with the reason.
TEST(ImportCommand, PositiveBaIsKeptAndANonConstantBaIsRefusedWithItsReason) {
  std::string text = kV1Deck;
  text.replace(text.find("-0.8      0.8"), 4, "3.5e5");
  const fs::path deck = write_temp_file(kFolder, "ba.dat", text);
  const fs::path out = deck.parent_path() / "ba";
  fs::remove_all(out);
  CliRun run = run_cli("import moordyn " + deck.string() + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string scene = read_text(out / "ba-line-1.toml");
  EXPECT_EQ(value_of(scene, "axial_damping"), 3.5e5) << scene;
  EXPECT_EQ(scene.find("is a damping ratio"), std::string::npos) << scene;

  text.replace(text.find("3.5e5"), 5, "ba.csv");
  const fs::path curve = write_temp_file(kFolder, "ba-curve.dat", text);
  run = run_cli("import moordyn " + curve.string() + " --out " +
                (curve.parent_path() / "ba-curve").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("not converted: BA 'ba.csv' is not a constant"), std::string::npos)
      << run.output;
}

TEST(ImportCommand, UnknownSectionExitsTwoNamingTheLineAndWritesNothing) {
  std::string text = kV1Deck;
  text.insert(text.find("---------------------- SOLVER OPTIONS"),
              "---------------------- MYSTERY ---------\n");
  const fs::path deck = write_temp_file(kFolder, "mystery.dat", text);
  const fs::path out = deck.parent_path() / "mystery";
  fs::remove_all(out);
  const CliRun run = run_cli("import moordyn " + deck.string() + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("mystery.dat:22: unknown section 'MYSTERY'"), std::string::npos)
      << run.output;
  EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out));
}

TEST(ImportCommand, NonNumericValueExitsTwoNamingLineAndColumn) {
  std::string text = kV1Deck;
  text.replace(text.find("100.0         8.0e8"), 5, "heavy");
  const fs::path deck = write_temp_file(kFolder, "bad-value.dat", text);
  const CliRun run = run_cli("import moordyn " + deck.string() + " --out " +
                             (deck.parent_path() / "bad").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("bad-value.dat:5: 'MassDen': 'heavy' is not a number"),
            std::string::npos)
      << run.output;
}

}  // namespace
}  // namespace catena::testing
