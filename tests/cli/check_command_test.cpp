// SPDX-License-Identifier: MIT
// `catena check` end to end on the repository's mooring line (verification/scenes/physical/
// mooring-line-900m.toml): Catena's own reference frequencies are read back from a first run's
// JSON, a synthetic "other program" is built from them (f_ref (1 - c / N^2) + bias at four
// resolutions), and the command must recover the order and the bias, give the right verdicts and
// exit codes, and refuse bad input (exit 2, naming row and column) without writing anything.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/cli_support.hpp"

namespace catena::testing {
namespace {

namespace fs = std::filesystem;

const std::string kScene =
    std::string(CATENA_SOURCE_DIR) + "/verification/scenes/physical/mooring-line-900m.toml";
constexpr const char* kFolder = "catena_check_test";

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// Catena's in-plane and out-of-plane reference omegas for modes 1-3 [rad/s], from a run of the
// command itself (so the test holds no hard-coded frequency).
std::vector<std::vector<double>> reference_omegas() {
  const fs::path results = write_temp_file(
      kFolder, "probe.csv", "plane,mode,omega_rad_s\nin-plane,3,1.0\nout-of-plane,3,1.0\n");
  const fs::path json = results.parent_path() / "probe.json";
  run_cli("check " + results.string() + " --scene " + kScene + " --json " + json.string());
  std::vector<std::vector<double>> omegas(2);
  const nlohmann::json document = read_json(json);
  for (const auto& reference : document.at("references")) {
    const int plane = reference.at("plane").get<std::string>() == "in-plane" ? 0 : 1;
    for (const auto& mode : reference.at("modes"))
      omegas[plane].push_back(mode.at("omega_rad_s").get<double>());
  }
  return omegas;
}

// Modes 1-3 of both planes at N = 20, 40, 80, 160: f_ref (1 - c / N^2) (1 + relative_bias).
std::string synthetic_code(double c, double relative_bias) {
  const auto omegas = reference_omegas();
  std::string csv = "plane,mode,resolution,omega_rad_s\n";
  for (int plane = 0; plane < 2; ++plane) {
    for (int mode = 1; mode <= 3; ++mode) {
      const double f = omegas[static_cast<std::size_t>(plane)][static_cast<std::size_t>(mode - 1)];
      for (double n : {20.0, 40.0, 80.0, 160.0}) {
        csv += fmt::format("{},{},{},{:.17g}\n", plane == 0 ? "In-Plane" : "OUTOFPLANE", mode, n,
                           f * (1.0 - c / (n * n)) + relative_bias * f);
      }
    }
  }
  return csv;
}

TEST(CheckCommand, BiasedCodeConvergesToAWrongLimitWithOrderTwo) {
  const double bias = 0.01;
  const fs::path results = write_temp_file(kFolder, "biased.csv", synthetic_code(3.0, bias));
  const fs::path json = results.parent_path() / "biased.json";
  const fs::path out = results.parent_path() / "biased-report";
  const CliRun run = run_cli("check " + results.string() + " --scene " + kScene + " --json " +
                             json.string() + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 1) << run.output;
  const auto document = read_json(json);
  ASSERT_EQ(document.at("modes").size(), 6u);
  for (const auto& mode : document.at("modes")) {
    EXPECT_EQ(mode.at("verdict").get<std::string>(), "converges to a wrong limit") << mode.dump();
    EXPECT_NEAR(mode.at("study").at("observed_order").get<double>(), 2.0, 1e-4);
    EXPECT_NEAR(mode.at("study").at("bias_relative").get<double>(), bias, 1e-3 * bias);
  }
  // Trustworthy studies: their order and bias are printed unmarked.
  EXPECT_NE(run.output.find(" 2.000 "), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("? not trusted"), std::string::npos) << run.output;
  EXPECT_TRUE(fs::exists(out / "check.html"));
  EXPECT_TRUE(fs::exists(out / "check.md"));
  EXPECT_TRUE(fs::exists(out / "figures" / "outofplane-mode-3.svg"));
}

// A study whose order is not stable across triples (order 2 from the three coarsest resolutions,
// 1.3 from the three finest) is judged untrustworthy: the terminal table still prints what the
// fit gave, marked "?", with the study's reason under the table.
TEST(CheckCommand, UntrustworthyStudyIsMarkedInTheTerminalTable) {
  const auto omegas = reference_omegas();
  const double c = 3.0;
  // Errors c/N^2 at N = 20, 40, 80, then the N = 160 value that makes the finest triple's order
  // log2((e40 - e80) / (e80 - e160)) = 1.3.
  const double e80 = c / 6400.0;
  const double e160 = e80 - (c / 1600.0 - e80) / std::pow(2.0, 1.3);
  std::string csv = "plane,mode,resolution,omega_rad_s\n";
  for (const auto& [n, error] : std::vector<std::pair<int, double>>{
           {20, c / 400.0}, {40, c / 1600.0}, {80, e80}, {160, e160}}) {
    csv += fmt::format("in-plane,1,{},{:.17g}\n", n, omegas[0][0] * (1.0 - error));
  }
  const fs::path results = write_temp_file(kFolder, "unstable.csv", csv);
  const fs::path json = results.parent_path() / "unstable.json";
  const CliRun run =
      run_cli("check " + results.string() + " --scene " + kScene + " --json " + json.string());
  const auto study = read_json(json).at("modes").at(0).at("study");
  ASSERT_FALSE(study.at("trustworthy").get<bool>()) << study.dump();
  const double order = study.at("observed_order").get<double>();
  EXPECT_NEAR(order, 1.3, 1e-6);
  EXPECT_NE(run.output.find(fmt::format("{:.3f}?", order)), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("? not trusted"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("in-plane mode 1: " + study.at("note").get<std::string>()),
            std::string::npos)
      << run.output;
}

TEST(CheckCommand, UnbiasedCodeIsConvergedOrNotYetWithinTolerance) {
  const fs::path good = write_temp_file(kFolder, "unbiased.csv", synthetic_code(3.0, 0.0));
  const CliRun converged = run_cli("check " + good.string() + " --scene " + kScene);
  EXPECT_EQ(converged.exit_code, 0) << converged.output;
  EXPECT_NE(converged.output.find("converged"), std::string::npos) << converged.output;
  // c = 40: the finest error 40 / 160^2 = 1.6e-3 exceeds rtol 1e-3, but the limit is right.
  const fs::path slow = write_temp_file(kFolder, "slow.csv", synthetic_code(40.0, 0.0));
  const CliRun not_yet = run_cli("check " + slow.string() + " --scene " + kScene);
  EXPECT_EQ(not_yet.exit_code, 1) << not_yet.output;
  EXPECT_NE(not_yet.output.find("converges, not yet within tolerance"), std::string::npos)
      << not_yet.output;
  EXPECT_EQ(not_yet.output.find("wrong limit"), std::string::npos) << not_yet.output;
}

struct BadInput {
  const char* name;
  const char* csv;
  const char* expected;  // part of the message
};

TEST(CheckCommand, BadInputExitsTwoNamingRowAndColumnAndWritesNothing) {
  const BadInput cases[] = {
      {"missing-column", "plane,frequency_hz\nin-plane,0.1\n", "missing column 'mode'"},
      {"no-frequency", "plane,mode\nin-plane,1\n", "frequency_hz"},
      {"unknown-plane", "plane,mode,frequency_hz\nin-plane,1,0.1\nsideways,2,0.2\n",
       "row 2 (line 3), column 'plane'"},
      {"duplicate", "plane,mode,frequency_hz\ninplane,1,0.1\nIn-Plane,1,0.11\n",
       "duplicate in-plane mode 1"},
      {"non-numeric", "plane,mode,frequency_hz\nin-plane,1,abc\n", "column 'frequency_hz': 'abc'"},
      {"nan", "plane,mode,frequency_hz\nin-plane,1,nan\n", "row 1 (line 2), column 'frequency_hz'"},
      {"empty", "", "no header"},
      {"header-only", "plane,mode,frequency_hz\n", "no data rows"},
      {"unknown-column", "plane,mode,frequency_hz,colour\nin-plane,1,0.1,red\n",
       "unknown column 'colour'"},
      {"bad-mode", "plane,mode,frequency_hz\nin-plane,1.5,0.1\n", "column 'mode'"},
  };
  for (const auto& c : cases) {
    const fs::path results = write_temp_file(kFolder, std::string(c.name) + ".csv", c.csv);
    const fs::path json = results.parent_path() / (std::string(c.name) + "-out.json");
    const fs::path out = results.parent_path() / (std::string(c.name) + "-report");
    fs::remove(json);
    fs::remove_all(out);
    const CliRun run = run_cli("check " + results.string() + " --scene " + kScene + " --json " +
                               json.string() + " --out " + out.string());
    EXPECT_EQ(run.exit_code, 2) << c.name << "\n" << run.output;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << c.name << "\n" << run.output;
    EXPECT_FALSE(fs::exists(json)) << c.name;
    EXPECT_FALSE(fs::exists(out / "check.md")) << c.name;
  }
}

TEST(CheckCommand, JsonResultsWithShapesArePairedByMac) {
  // Catena's own first two out-of-plane modes, sampled at 11 stations, given as the other
  // program's modes 2 and 1 (swapped numbers): MAC pairs them back.
  const fs::path probe = write_temp_file(kFolder, "probe-shapes.json", R"({"results": [
    {"plane": "out-of-plane", "mode": 1, "omega_rad_s": 1.0,
     "shape": {"s_m": [0, 500, 1000], "v": [0, 1, 0]}}]})");
  const fs::path json = probe.parent_path() / "probe-shapes-out.json";
  const CliRun first =
      run_cli("check " + probe.string() + " --scene " + kScene + " --json " + json.string());
  ASSERT_NE(first.exit_code, 2) << first.output;
  const nlohmann::json probed = read_json(json);
  const auto& modes = probed.at("references").at(0).at("modes");
  const double f1 = modes.at(0).at("omega_rad_s").get<double>();
  const double f2 = modes.at(1).at("omega_rad_s").get<double>();
  // Mode 1 of a sagging line out of plane is close to a half sine, mode 2 to a full sine.
  std::string stations = "[0,100,200,300,400,500,600,700,800,900,1000]";
  std::string half = "[0,0.309,0.588,0.809,0.951,1,0.951,0.809,0.588,0.309,0]";
  std::string full = "[0,0.588,0.951,0.951,0.588,0,-0.588,-0.951,-0.951,-0.588,0]";
  const fs::path swapped = write_temp_file(kFolder, "swapped.json",
                                           fmt::format(R"({{"results": [
    {{"plane": "out-of-plane", "mode": 1, "omega_rad_s": {:.17g}, "shape": {{"s_m": {}, "v": {}}}}},
    {{"plane": "out-of-plane", "mode": 2, "omega_rad_s": {:.17g}, "shape": {{"s_m": {}, "v": {}}}}}]}})",
                                                       f2, stations, full, f1, stations, half));
  const fs::path out = probe.parent_path() / "swapped-out.json";
  const CliRun run =
      run_cli("check " + swapped.string() + " --scene " + kScene + " --json " + out.string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  const auto document = read_json(out);
  EXPECT_EQ(document.at("modes").at(0).at("reference_index"), 2) << run.output;
  EXPECT_EQ(document.at("modes").at(1).at("reference_index"), 1) << run.output;
  EXPECT_GT(document.at("modes").at(0).at("resolutions").at(0).at("mac").get<double>(), 0.95);
}

// ---- Time series (docs/how-to/check-time-series.md): a free decay written here in MoorDyn v2's
// layout from Catena's own damped modes of the damped mooring line (read back from `catena solve
// --json`, so no frequency is hard-coded), then checked by the command: exit 0 when it is Catena's
// decay, 1 with one frequency 1 % off, 2 for each bad input named; the JSON keys of issue 33.

const std::string kDampedScene =
    std::string(CATENA_SOURCE_DIR) + "/verification/scenes/damped/mooring-line-900m-damped.toml";

// Catena's first three in-plane damped modes (frequency [Hz], damping ratio) from `catena solve`.
std::vector<std::pair<double, double>> damped_modes() {
  const fs::path json = fs::temp_directory_path() / kFolder / "damped-solve.json";
  fs::create_directories(json.parent_path());
  const CliRun run = run_cli("solve " + kDampedScene + " --json " + json.string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  // The document outlives the loop (a range-for over a member of a temporary would not).
  const nlohmann::json document = read_json(json);
  std::vector<std::pair<double, double>> modes;
  for (const auto& m :
       document.at("scenes")[0].at("solvers").at("shooting").at("inplane").at("modes")) {
    if (modes.size() < 3)
      modes.emplace_back(m.at("frequency_hz").get<double>(), m.at("damping_ratio").get<double>());
  }
  return modes;
}

// MoorDyn v2's main output (setw(10) time with 4 decimals, setw(20) values), 0.1 s for 300 s:
// FAIRTEN1 = 1e6 + sum_k 3e4/k e^(-delta t) cos(omega t + k) with mode 2 scaled by `factor`.
std::string moordyn_decay(double factor) {
  const auto modes = damped_modes();
  std::string text = fmt::format("{:>10}{:>20}\n{:>10}{:>20}\n", "Time", "FAIRTEN1", "(s)", "(N)");
  for (int i = 0; i <= 3000; ++i) {
    const double t = 0.1 * i;
    double value = 1e6;
    for (std::size_t k = 0; k < modes.size(); ++k) {
      const double omega = 2 * M_PI * modes[k].first * (k == 1 ? factor : 1.0);
      const double zeta = modes[k].second;
      const double delta = zeta * omega / std::sqrt(1 - zeta * zeta);
      value += 3e4 / double(k + 1) * std::exp(-delta * t) * std::cos(omega * t + double(k));
    }
    text += fmt::format("{:>10.4f}{:>20.7e}\n", t, value);  // MoorDyn prints 7 decimals
  }
  return text;
}

TEST(CheckCommand, TimeSeriesOfCatenasDecayAgreesAndWritesTheIssuesKeys) {
  const fs::path decay = write_temp_file(kFolder, "decay.out", moordyn_decay(1.0));
  const fs::path json = decay.parent_path() / "decay.json";
  const CliRun run = run_cli("check " + decay.string() + " --scene " + kDampedScene +
                             " --channel FAIRTEN1 --window 1: --json " + json.string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("agrees"), std::string::npos) << run.output;
  const auto document = read_json(json);
  ASSERT_EQ(document.at("modes").size(), 3u) << document.dump(1);
  for (const auto& mode : document.at("modes")) {
    for (const char* key : {"plane", "mode", "identified_frequency_hz", "frequency_uncertainty_hz",
                            "identified_damping_ratio", "damping_ratio_uncertainty",
                            "catena_frequency_hz", "catena_damping_ratio", "verdict"})
      EXPECT_TRUE(mode.contains(key)) << key;
    EXPECT_EQ(mode.at("verdict").get<std::string>(), "agrees") << mode.dump();
    EXPECT_EQ(mode.at("plane").get<std::string>(), "in-plane");
  }
  EXPECT_EQ(document.at("counts").at("agrees").get<int>(), 3);
  EXPECT_FALSE(document.at("failed").get<bool>());
}

TEST(CheckCommand, TimeSeriesOnePercentOffExitsOne) {
  const fs::path decay = write_temp_file(kFolder, "decay-off.out", moordyn_decay(1.01));
  const CliRun run =
      run_cli("check " + decay.string() + " --scene " + kDampedScene + " --channel FAIRTEN1");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("disagrees"), std::string::npos) << run.output;
}

TEST(CheckCommand, TimeSeriesBadInputExitsTwoNamingTheProblem) {
  const std::string good = moordyn_decay(1.0);
  std::string nan = good;
  nan.replace(nan.find("\n", nan.find("0.5000")) - 16, 16, fmt::format("{:>16}", "nan"));
  std::string backwards = good;
  backwards.replace(backwards.find("    0.5000"), 10, "    0.3000");
  struct Case {
    const char* name;
    std::string text;
    std::string options;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"no-rows", "      Time            FAIRTEN1\n       (s)                 (N)\n",
       "--channel FAIRTEN1", "no data rows"},
      {"backwards", backwards, "--channel FAIRTEN1", "line 8: time 0.3 s is not after"},
      {"missing", good, "--channel FAIRTEN2", "no channel 'FAIRTEN2'"},
      {"no-channel", good, "", "--channel: which channel"},
      {"nan", nan, "--channel FAIRTEN1", "line 8 (time 0.5 s), channel 'FAIRTEN1'"},
      {"short", good, "--channel FAIRTEN1 --window 10:20", "shorter than two periods"},
      {"window", good, "--channel FAIRTEN1 --window 10:x", "--window 10:x"},
      {"plane", good, "--channel FAIRTEN1 --plane sideways", "--plane sideways"}};
  for (const auto& c : cases) {
    const fs::path file = write_temp_file(kFolder, std::string(c.name) + ".out", c.text);
    const fs::path json = file.parent_path() / (std::string(c.name) + ".json");
    fs::remove(json);
    const CliRun run = run_cli("check " + file.string() + " --scene " + kDampedScene + " " +
                               c.options + " --json " + json.string());
    EXPECT_EQ(run.exit_code, 2) << c.name << "\n" << run.output;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << c.name << "\n" << run.output;
    EXPECT_FALSE(fs::exists(json)) << c.name;
  }
  // A results file refuses the time-series options, and the other way round.
  const fs::path results =
      write_temp_file(kFolder, "r.csv", "plane,mode,frequency_hz\nin-plane,1,0.06\n");
  const CliRun mixed =
      run_cli("check " + results.string() + " --scene " + kDampedScene + " --channel FAIRTEN1");
  EXPECT_EQ(mixed.exit_code, 2) << mixed.output;
  EXPECT_NE(mixed.output.find("--channel is for a time series"), std::string::npos) << mixed.output;
}

}  // namespace
}  // namespace catena::testing
